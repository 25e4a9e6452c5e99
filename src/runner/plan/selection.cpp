#include "runner/plan/selection.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "runner/model/test_id.h"
#include "runner/plan/run_gate.h"

namespace robottestingframework {
namespace runner {

namespace {

// Tags compare without case and spaces, as Robot Framework's do.
std::string normalized(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c != ' ' && c != '\t') {
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
    }
    return out;
}

struct Token {
    enum class Kind { Tag, And, Or, Not } kind;
    std::string text;
    std::size_t column;  // 1-based
};

// The operators need no spaces around them ("armANDslow"), as in Robot Framework.
std::vector<Token> tokenize(const std::string& text) {
    std::vector<Token> tokens;
    std::string tag;
    std::size_t tagColumn = 0;
    auto endTag = [&] {
        if (!normalized(tag).empty()) {
            tokens.push_back({Token::Kind::Tag, normalized(tag), tagColumn});
        }
        tag.clear();
    };
    for (std::size_t i = 0; i < text.size();) {
        const struct {
            const char* word;
            Token::Kind kind;
        } operators[] = {{"AND", Token::Kind::And},
                         {"&", Token::Kind::And},
                         {"OR", Token::Kind::Or},
                         {"NOT", Token::Kind::Not}};
        bool found = false;
        for (const auto& op : operators) {
            const std::size_t length = std::char_traits<char>::length(op.word);
            if (text.compare(i, length, op.word) == 0) {
                endTag();
                tokens.push_back({op.kind, op.word, i + 1});
                i += length;
                found = true;
                break;
            }
        }
        if (!found) {
            if (tag.empty() || normalized(tag).empty()) {
                tagColumn = i + 1;
            }
            tag += text[i++];
        }
    }
    endTag();
    return tokens;
}

}  // namespace

struct TagExpression::Node {
    Token::Kind kind = Token::Kind::Tag;
    std::string pattern;
    std::unique_ptr<Node> left;  // null for a leading NOT
    std::unique_ptr<Node> right;

    bool matches(const std::vector<std::string>& tags) const {
        switch (kind) {
            case Token::Kind::Tag:
                return std::any_of(tags.begin(), tags.end(), [this](const std::string& tag) {
                    return globMatches(pattern, normalized(tag));
                });
            case Token::Kind::And:
                return left->matches(tags) && right->matches(tags);
            case Token::Kind::Or:
                return left->matches(tags) || right->matches(tags);
            case Token::Kind::Not:
                return (!left || left->matches(tags)) && !right->matches(tags);
        }
        return false;
    }
};

namespace {

class ExpressionParser {
public:
    explicit ExpressionParser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

    // Lowest first: NOT, then OR, then AND.
    std::unique_ptr<TagExpression::Node> parseNot() {
        std::unique_ptr<TagExpression::Node> left;
        if (!atKind(Token::Kind::Not)) {
            left = parseBinary(Token::Kind::Or);
        }
        while (atKind(Token::Kind::Not)) {
            const Token& op = tokens_[next_++];
            auto node = std::make_unique<TagExpression::Node>();
            node->kind = Token::Kind::Not;
            node->left = std::move(left);
            node->right = operand(op, [this] { return parseBinary(Token::Kind::Or); });
            left = std::move(node);
        }
        return left;
    }

    bool done() const { return next_ == tokens_.size(); }
    const Token& current() const { return tokens_[next_]; }

private:
    bool atKind(Token::Kind kind) const { return !done() && tokens_[next_].kind == kind; }

    template <typename Parse>
    std::unique_ptr<TagExpression::Node> operand(const Token& op, Parse parse) {
        if (done() || tokens_[next_].kind != Token::Kind::Tag) {
            throw std::string("no tag after " + op.text + " at column " +
                              std::to_string(op.column));
        }
        return parse();
    }

    std::unique_ptr<TagExpression::Node> parseBinary(Token::Kind kind) {
        auto left = kind == Token::Kind::Or ? parseBinary(Token::Kind::And) : parseTag();
        while (atKind(kind)) {
            const Token& op = tokens_[next_++];
            auto node = std::make_unique<TagExpression::Node>();
            node->kind = kind;
            node->left = std::move(left);
            node->right = operand(op, [this, kind] {
                return kind == Token::Kind::Or ? parseBinary(Token::Kind::And) : parseTag();
            });
            left = std::move(node);
        }
        return left;
    }

    std::unique_ptr<TagExpression::Node> parseTag() {
        if (done()) {
            throw std::string("no tag at the end");
        }
        const Token& token = tokens_[next_];
        if (token.kind != Token::Kind::Tag) {
            throw std::string("no tag before " + token.text + " at column " +
                              std::to_string(token.column));
        }
        ++next_;
        auto node = std::make_unique<TagExpression::Node>();
        node->pattern = token.text;
        return node;
    }

    std::vector<Token> tokens_;
    std::size_t next_ = 0;
};

}  // namespace

TagExpression::TagExpression() = default;
TagExpression::~TagExpression() = default;
TagExpression::TagExpression(TagExpression&&) noexcept = default;
TagExpression& TagExpression::operator=(TagExpression&&) noexcept = default;

bool TagExpression::parse(const std::string& text, TagExpression& expression, std::string& error) {
    std::vector<Token> tokens = tokenize(text);
    if (tokens.empty()) {
        error = "an empty tag expression (expected e.g. arm, armANDslow, arm OR leg, NOT slow)";
        return false;
    }
    ExpressionParser parser(tokens);
    try {
        expression.root_ = parser.parseNot();
        if (!parser.done()) {
            throw std::string("unexpected " + parser.current().text + " at column " +
                              std::to_string(parser.current().column));
        }
    } catch (const std::string& problem) {
        error =
            problem + " of '" + text + "' (expected e.g. arm, armANDslow, arm OR leg, NOT slow)";
        return false;
    }
    return true;
}

bool TagExpression::matches(const std::vector<std::string>& tags) const {
    return root_ && root_->matches(tags);
}

namespace {

// The bytes of the character at `at`: a UTF-8 sequence whole (2 to 4 bytes), else one byte (ASCII,
// or a byte that starts no well-formed sequence).
std::size_t characterLength(const std::string& text, std::size_t at) {
    const auto lead = static_cast<unsigned char>(text[at]);
    const std::size_t length = lead >= 0xF0 && lead <= 0xF4   ? 4
                               : lead >= 0xE0 && lead <= 0xEF ? 3
                               : lead >= 0xC2 && lead <= 0xDF ? 2
                                                              : 1;
    if (length == 1 || at + length > text.size()) {
        return 1;
    }
    for (std::size_t i = 1; i < length; ++i) {
        if ((static_cast<unsigned char>(text[at + i]) & 0xC0) != 0x80) {
            return 1;
        }
    }
    return length;
}

// "*", "?" glob over the whole text; with `escapes`, "\\x" in `pattern` stands for a literal x.
// '?' is one character, not one byte ("u/?" matches "u/ü"), and '*' gives back whole
// characters. Iterative, with one backtrack point: linear enough for names and tags.
bool matchGlob(const std::string& pattern, const std::string& text, bool escapes) {
    std::size_t p = 0;
    std::size_t t = 0;
    std::size_t star = std::string::npos;
    std::size_t mark = 0;
    while (t < text.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            mark = t;
            continue;
        }
        const bool escaped = escapes && p + 1 < pattern.size() && pattern[p] == '\\';
        const bool one = p < pattern.size() && !escaped && pattern[p] == '?';
        if (p < pattern.size() && (one || pattern[p + (escaped ? 1 : 0)] == text[t])) {
            p += escaped ? 2 : 1;
            t += one ? characterLength(text, t) : 1;
        } else if (star != std::string::npos) {
            p = star + 1;
            mark += characterLength(text, mark);
            t = mark;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') {
        ++p;
    }
    return p == pattern.size();
}

bool escapedGlobMatches(const std::string& pattern, const std::string& text) {
    return matchGlob(pattern, text, true);
}

}  // namespace

bool globMatches(const std::string& pattern, const std::string& text) {
    return matchGlob(pattern, text, false);
}

bool NameFilter::parse(const std::string& text, NameFilter& filter, std::string& error) {
    const std::string example =
        " (expected e.g. 'arm/*', 'arm/*:leg/*-*slow*', 'arm/*\\-fast' for a literal '-')";
    if (text.empty()) {
        error = "an empty filter" + example;
        return false;
    }
    NameFilter parsed;
    parsed.text_ = text;
    std::vector<std::string>* into = &parsed.positive_;
    std::string pattern;
    std::size_t start = 0;  // where `pattern` began, for messages
    auto end = [&](std::size_t at) {
        if (pattern.empty()) {
            // A leading '-' means "every test but": no positive pattern before it.
            if (!(into == &parsed.positive_ && at == 0 && text[0] == '-')) {
                error = "an empty pattern at column " + std::to_string(start + 1) + " of '" + text +
                        "'" + example;
                return false;
            }
        } else {
            into->push_back(pattern);
        }
        pattern.clear();
        start = at + 1;
        return true;
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\\') {
            if (i + 1 == text.size()) {
                error = "a '\\' at the end of '" + text + "' escapes nothing" + example;
                return false;
            }
            pattern += text.substr(i, 2);
            ++i;
        } else if (c == ':') {
            if (!end(i)) {
                return false;
            }
        } else if (c == '-' && into == &parsed.positive_) {
            // The first '-' starts the negative patterns; a later one is literal there, as in
            // GoogleTest.
            if (!end(i)) {
                return false;
            }
            into = &parsed.negative_;
        } else {
            pattern += c;
        }
    }
    if (!end(text.size())) {
        return false;
    }
    if (parsed.positive_.empty()) {
        parsed.positive_.push_back("*");
    }
    filter = std::move(parsed);
    return true;
}

NameFilter NameFilter::exactIdOnly(const std::string& text, const std::string& notAPattern) {
    NameFilter filter;
    filter.text_ = text;
    filter.notAPattern_ = notAPattern;
    return filter;  // no pattern: matches() is false, the id alone selects (selected())
}

bool NameFilter::matches(const std::string& id) const {
    auto any = [&id](const std::vector<std::string>& patterns) {
        return std::any_of(patterns.begin(), patterns.end(), [&id](const std::string& pattern) {
            return escapedGlobMatches(pattern, id);
        });
    };
    return any(positive_) && !any(negative_);
}

std::string filterNamingNoTest(const std::vector<SuiteSpec>& suites, const Selection& selection) {
    for (const auto& filter : selection.filters) {
        if (filter.notAPattern().empty()) {
            continue;
        }
        const bool named = std::any_of(suites.begin(), suites.end(), [&](const SuiteSpec& suite) {
            return std::any_of(suite.tests.begin(), suite.tests.end(), [&](const TestSpec& test) {
                return testId(suite, test) == filter.text();
            });
        });
        if (!named) {
            return "--filter " + filter.text() + ": " + filter.notAPattern() +
                   "; nor is it the id of a test of this run";
        }
    }
    return {};
}

namespace {

// `ids`: the id of every test of the run, for the filters that name one as written.
bool selected(const Selection& selection, const SuiteSpec& suite, const TestSpec& test,
              const std::set<std::string>& ids) {
    const std::string id = testId(suite, test);
    for (const auto& filter : selection.filters) {
        const bool exact = ids.count(filter.text()) != 0;
        if (exact ? filter.text() != id : !filter.matches(id)) {
            return false;
        }
    }
    for (const auto& keyword : selection.keywords) {
        if (!keyword.matches(id, test.tags)) {
            return false;
        }
    }
    for (const auto& expression : selection.exclude) {
        if (expression.matches(test.tags)) {
            return false;
        }
    }
    return selection.include.empty() ||
           std::any_of(selection.include.begin(), selection.include.end(),
                       [&test](const TagExpression& e) { return e.matches(test.tags); });
}

}  // namespace

void applySelection(std::vector<SuiteSpec>& suites, const Selection& selection) {
    if (selection.empty()) {
        return;
    }
    std::vector<std::vector<bool>> keep;
    std::vector<const TestSpec*> left;  // the tests not selected
    std::vector<const TestSpec*> kept;
    std::set<std::string> ids;
    for (const auto& suite : suites) {
        for (const auto& test : suite.tests) {
            ids.insert(testId(suite, test));
        }
    }
    for (const auto& suite : suites) {
        keep.emplace_back();
        for (const auto& test : suite.tests) {
            keep.back().push_back(selected(selection, suite, test, ids));
            (keep.back().back() ? kept : left).push_back(&test);
        }
    }
    for (std::size_t s = 0; s < suites.size(); ++s) {
        for (std::size_t t = 0; t < suites[s].tests.size(); ++t) {
            TestSpec& test = suites[s].tests[t];
            if (!keep[s][t]) {
                continue;
            }
            // A dependency only on tests left out: skipped, and said why.
            std::vector<std::string> depends;
            for (const auto& dependency : test.depends) {
                auto namedBy = [&dependency](const TestSpec* other) {
                    return dependencyNames(dependency, *other);
                };
                if (std::none_of(kept.begin(), kept.end(), namedBy) &&
                    std::any_of(left.begin(), left.end(), namedBy)) {
                    if (test.skipReason.empty()) {
                        test.skipReason = "depends on " + dependency + ", which is not selected";
                    }
                } else {
                    depends.push_back(dependency);
                }
            }
            test.depends = std::move(depends);
        }
    }
    std::vector<SuiteSpec> chosen;
    for (std::size_t s = 0; s < suites.size(); ++s) {
        std::vector<TestSpec> tests;
        for (std::size_t t = 0; t < suites[s].tests.size(); ++t) {
            if (keep[s][t]) {
                tests.push_back(std::move(suites[s].tests[t]));
            }
        }
        if (!tests.empty()) {
            suites[s].tests = std::move(tests);
            chosen.push_back(std::move(suites[s]));
        }
    }
    suites = std::move(chosen);
}

}  // namespace runner
}  // namespace robottestingframework
