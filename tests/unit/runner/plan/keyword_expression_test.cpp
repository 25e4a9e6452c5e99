// -k EXPR: pytest's keyword expressions over a test's id and tags.
#include <gtest/gtest.h>

#include "runner/plan/keyword_expression.h"
#include "runner/plan/selection.h"

using namespace robottestingframework::runner;

namespace {

bool keywordMatches(const std::string& text, const std::string& id,
                    const std::vector<std::string>& tags = {}) {
    KeywordExpression expression;
    std::string error;
    EXPECT_TRUE(KeywordExpression::parse(text, expression, error)) << error;
    return expression.matches(id, tags);
}

std::string keywordError(const std::string& text) {
    KeywordExpression expression;
    std::string error;
    EXPECT_FALSE(KeywordExpression::parse(text, expression, error)) << text;
    return error;
}

}  // namespace

TEST(KeywordExpression, ANameIsASubstringOfTheIdWithoutCase) {
    EXPECT_TRUE(keywordMatches("speed", "robot/t.py[--speed 80]"));
    EXPECT_TRUE(keywordMatches("ROBOT", "robot/t.py[--speed 80]"));  // the suite's name
    EXPECT_TRUE(keywordMatches("t.py[--speed", "robot/t.py[--speed 80]"));
    EXPECT_FALSE(keywordMatches("gripper", "robot/t.py[--speed 80]"));
}

TEST(KeywordExpression, ANameIsASubstringOfATagToo) {
    EXPECT_TRUE(keywordMatches("night", "s/a", {"Nightly"}));
    EXPECT_FALSE(keywordMatches("weekly", "s/a", {"Nightly"}));
}

TEST(KeywordExpression, NotBindsTighterThanAndAndAndTighterThanOr) {
    EXPECT_TRUE(keywordMatches("a and b or c", "x/c"));  // (a and b) or c
    EXPECT_FALSE(keywordMatches("a and (b or c)", "x/c"));
    EXPECT_TRUE(keywordMatches("not slow and arm", "s/arm"));
    EXPECT_FALSE(keywordMatches("not slow and arm", "s/arm-slow"));
    EXPECT_TRUE(keywordMatches("not (slow or leg)", "s/arm"));
    EXPECT_TRUE(keywordMatches("not not arm", "s/arm"));
    EXPECT_TRUE(keywordMatches("(arm or leg) and not slow", "s/leg"));
}

TEST(KeywordExpression, TheOperatorsAreLowerCaseWordsAsInPytest) {
    EXPECT_TRUE(keywordMatches("AND", "s/band"));  // a name, not the operator
    EXPECT_TRUE(keywordMatches("android", "s/android"));
}

TEST(KeywordExpression, AMalformedExpressionSaysWhereAndWhatWasExpected) {
    EXPECT_EQ(keywordError("a and"),
              "at column 6: expected a name, 'not' or '('; got the end (e.g. -k 'speed and not "
              "slow', -k '(arm or leg) and grip')");
    EXPECT_NE(keywordError("(a or b").find("at column 8: expected ')' (for the '(' at column 1)"),
              std::string::npos);
    EXPECT_NE(keywordError("a b").find("at column 3: expected 'and', 'or' or the end; got the "
                                       "name 'b'"),
              std::string::npos);
    EXPECT_NE(keywordError("").find("at column 1: expected a name"), std::string::npos);
    EXPECT_NE(keywordError("a or )").find("at column 6: expected a name, 'not' or '('; got ')'"),
              std::string::npos);
}

TEST(KeywordExpression, SelectsWithTheOtherSelectionsAsAnAnd) {
    std::vector<SuiteSpec> suites(1);
    suites[0].name = "robot";
    for (const char* name : {"arm-fast", "arm-slow", "leg-fast"}) {
        TestSpec test;
        test.name = name;
        test.plugin = std::string(name) + ".so";
        suites[0].tests.push_back(test);
    }
    Selection selection;
    KeywordExpression keyword;
    std::string error;
    ASSERT_TRUE(KeywordExpression::parse("fast", keyword, error)) << error;
    selection.keywords.push_back(std::move(keyword));
    NameFilter filter;
    ASSERT_TRUE(NameFilter::parse("robot/arm*", filter, error)) << error;
    selection.filters.push_back(std::move(filter));
    applySelection(suites, selection);
    ASSERT_EQ(suites.size(), 1u);
    ASSERT_EQ(suites[0].tests.size(), 1u);
    EXPECT_EQ(suites[0].tests[0].name, "arm-fast");
}
