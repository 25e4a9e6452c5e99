// -k EXPR, as pytest's: names matched as substrings, without case, against a test's id
// ("suite/test", model/test_id.h), which holds its suite's name and its own, and against its
// tags; joined by `and`, `or`, `not` and parentheses (`not` binds tightest, then `and`, then
// `or`). "speed and not slow", "(arm or leg) and nightly".
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace robottestingframework {
namespace runner {

class KeywordExpression {
public:
    struct Node;
    KeywordExpression();
    ~KeywordExpression();
    KeywordExpression(KeywordExpression&&) noexcept;
    KeywordExpression& operator=(KeywordExpression&&) noexcept;

    // False with `error` ("at column N: expected ...; got ...") when `text` is not an
    // expression. A name is any run of characters but spaces and parentheses ("t.py[--speed",
    // "arm/grip"); `and`, `or`, `not` are words only in lower case, as pytest's.
    static bool parse(const std::string& text, KeywordExpression& expression, std::string& error);
    // `id`: the test's id; `tags`: its tags.
    bool matches(const std::string& id, const std::vector<std::string>& tags) const;
    const std::string& text() const { return text_; }

private:
    std::string text_;
    std::unique_ptr<Node> root_;
};

}  // namespace runner
}  // namespace robottestingframework
