// Which tests of the run are selected: --tag / --exclude-tag (tag expressions, as Robot
// Framework writes them) and --filter (name patterns on "suite/test", as GoogleTest writes
// them). A test not selected is not run and not reported.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "runner/model/suite_model.h"
#include "runner/plan/keyword_expression.h"

namespace robottestingframework {
namespace runner {

// "arm", "armANDslow", "arm OR leg", "arm NOT slow", "NOT slow", "a*", "l?g": AND (or &) binds
// tighter than OR, OR tighter than NOT; tags and patterns ignore case and spaces.
class TagExpression {
public:
    struct Node;
    TagExpression();
    ~TagExpression();
    TagExpression(TagExpression&&) noexcept;
    TagExpression& operator=(TagExpression&&) noexcept;

    // False with `error` ("... at column N of 'TEXT'") when `text` is not an expression.
    static bool parse(const std::string& text, TagExpression& expression, std::string& error);
    bool matches(const std::vector<std::string>& tags) const;

private:
    std::unique_ptr<Node> root_;
};

// "arm/*:leg/*-*slow*": patterns separated by ':', the negative ones after '-'; '*' any text,
// '?' one character (a '-' after the first is literal); matched against the whole test id
// ("suite/test", model/test_id.h). A '\' makes the next character literal: "*/arm\-fast" matches
// the id "s/arm-fast", and "\:", "\*", "\?" and "\\" likewise. A filter that is, as written,
// the id of a test of the run selects that test alone (applySelection), so any id can be given
// as it is shown, hyphens and all.
class NameFilter {
public:
    // False with `error` for an empty filter or pattern, or a '\' at the end.
    static bool parse(const std::string& text, NameFilter& filter, std::string& error);
    // A filter that does not parse ("arm::left/grip": an empty pattern at column 5) but may be a
    // test's id as --list shows it ("::", ":-", a '-' at the end): it selects that test alone,
    // and `notAPattern` is the usage error when no test of the run has that id
    // (filterNamingNoTest).
    static NameFilter exactIdOnly(const std::string& text, const std::string& notAPattern);
    bool matches(const std::string& id) const;
    const std::string& text() const { return text_; }
    const std::string& notAPattern() const { return notAPattern_; }

private:
    std::string text_;
    std::string notAPattern_;            // why text_ is no pattern; "" when it is one
    std::vector<std::string> positive_;  // with their '\' escapes
    std::vector<std::string> negative_;
};

struct Selection {
    std::vector<TagExpression> include;       // --tag: a test matching any is selected
    std::vector<TagExpression> exclude;       // --exclude-tag: a test matching any is not
    std::vector<NameFilter> filters;          // --filter: a test must match each
    std::vector<KeywordExpression> keywords;  // -k: a test must match each
    bool empty() const {
        return include.empty() && exclude.empty() && filters.empty() && keywords.empty();
    }
};

// "*", "?" glob, the whole text.
bool globMatches(const std::string& pattern, const std::string& text);

// "--filter TEXT: ..." for the first filter that is no pattern and no test's id either (an exact
// id wins over pattern syntax); "" when there is none.
std::string filterNamingNoTest(const std::vector<SuiteSpec>& suites, const Selection& selection);

// Takes out of `suites` the tests `selection` does not select, and the suites left without a
// test (their fixtures are then never set up). A selected test that depends on a test not
// selected is kept, to be skipped with that reason (TestSpec::skipReason).
void applySelection(std::vector<SuiteSpec>& suites, const Selection& selection);

}  // namespace runner
}  // namespace robottestingframework
