// Tag expressions, name filters and what applySelection leaves of a run.
#include <gtest/gtest.h>

#include "runner/plan/selection.h"

using namespace robottestingframework::runner;

namespace {

bool tagsMatch(const std::string& text, const std::vector<std::string>& tags) {
    TagExpression expression;
    std::string error;
    EXPECT_TRUE(TagExpression::parse(text, expression, error)) << error;
    return expression.matches(tags);
}

std::string tagError(const std::string& text) {
    TagExpression expression;
    std::string error;
    EXPECT_FALSE(TagExpression::parse(text, expression, error)) << text;
    return error;
}

TestSpec test(const std::string& name, std::vector<std::string> tags,
              std::vector<std::string> depends = {}) {
    TestSpec spec;
    spec.name = name;
    spec.plugin = name + ".so";
    spec.tags = std::move(tags);
    spec.depends = std::move(depends);
    return spec;
}

}  // namespace

TEST(TagExpression, AndBindsTighterThanOrAndOrTighterThanNot) {
    EXPECT_TRUE(tagsMatch("aANDbORc", {"c"}));  // (a AND b) OR c
    EXPECT_FALSE(tagsMatch("aANDbORc", {"a"}));
    EXPECT_FALSE(tagsMatch("a OR b NOT c", {"b", "c"}));  // (a OR b) NOT c
    EXPECT_TRUE(tagsMatch("a OR b NOT c", {"b"}));
    EXPECT_FALSE(tagsMatch("a NOT b NOT c", {"a", "c"}));
    EXPECT_TRUE(tagsMatch("NOT slow", {"arm"}));
    EXPECT_TRUE(tagsMatch("a & b", {"a", "b"}));
}

TEST(TagExpression, IgnoresCaseAndSpacesAndTakesPatterns) {
    EXPECT_TRUE(tagsMatch("Left Arm", {"left arm"}));
    EXPECT_TRUE(tagsMatch("l?ft*rm", {"LEFT ARM"}));
    EXPECT_FALSE(tagsMatch("arm", {"arms"}));
}

TEST(TagExpression, NamesTheMissingTagAndItsColumn) {
    EXPECT_NE(tagError("armAND").find("no tag after AND at column 4 of 'armAND'"),
              std::string::npos);
    EXPECT_NE(tagError("ORarm").find("no tag before OR at column 1"), std::string::npos);
    EXPECT_NE(tagError("").find("an empty tag expression"), std::string::npos);
}

TEST(NameFilter, MatchesPositivePatternsButNotNegativeOnes) {
    NameFilter filter;
    std::string error;
    ASSERT_TRUE(NameFilter::parse("arm/*:leg/knee-*slow*:arm/h?ad", filter, error)) << error;
    EXPECT_TRUE(filter.matches("arm/left"));
    EXPECT_TRUE(filter.matches("leg/knee"));
    EXPECT_FALSE(filter.matches("leg/hip"));
    EXPECT_FALSE(filter.matches("arm/slow left"));
    EXPECT_FALSE(filter.matches("arm/head"));
    ASSERT_TRUE(NameFilter::parse("-arm/*", filter, error)) << error;
    EXPECT_TRUE(filter.matches("leg/hip"));
    EXPECT_FALSE(filter.matches("arm/left"));
    EXPECT_FALSE(NameFilter::parse("a:", filter, error));
    EXPECT_NE(error.find("an empty pattern at column 3 of 'a:'"), std::string::npos) << error;
}

TEST(Selection, DropsUnselectedTestsAndEmptySuitesAndSaysWhyADependencyIsMissing) {
    SuiteSpec arm;
    arm.name = "arm";
    arm.tests = {test("left", {"arm"}), test("head", {"head"}, {"left"})};
    SuiteSpec legs;
    legs.name = "legs";
    legs.tests = {test("knee", {"leg"})};
    std::vector<SuiteSpec> suites{arm, legs};
    Selection selection;
    TagExpression head;
    std::string error;
    ASSERT_TRUE(TagExpression::parse("head", head, error)) << error;
    selection.include.push_back(std::move(head));
    applySelection(suites, selection);
    ASSERT_EQ(suites.size(), 1u);
    ASSERT_EQ(suites[0].tests.size(), 1u);
    EXPECT_EQ(suites[0].tests[0].name, "head");
    EXPECT_TRUE(suites[0].tests[0].depends.empty());
    EXPECT_EQ(suites[0].tests[0].skipReason, "depends on left, which is not selected");
}
