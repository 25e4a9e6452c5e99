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

TEST(NameFilter, ABackslashMakesAHyphenAColonOrAStarLiteral) {
    NameFilter filter;
    std::string error;
    ASSERT_TRUE(NameFilter::parse("*/arm\\-fast*", filter, error)) << error;
    EXPECT_TRUE(filter.matches("s/arm-fast.py"));
    EXPECT_FALSE(filter.matches("s/arm"));
    EXPECT_FALSE(filter.matches("s/armXfast"));
    ASSERT_TRUE(NameFilter::parse("s/a\\:b\\*:x-*\\-slow", filter, error)) << error;
    EXPECT_TRUE(filter.matches("s/a:b*"));
    EXPECT_FALSE(filter.matches("s/a:bc"));
    EXPECT_TRUE(filter.matches("x"));
    ASSERT_TRUE(NameFilter::parse("*-*\\-slow", filter, error)) << error;
    EXPECT_FALSE(filter.matches("s/a-slow"));
    EXPECT_TRUE(filter.matches("s/a-fast"));
    ASSERT_TRUE(NameFilter::parse("*-*a-b", filter, error)) << error;  // GoogleTest's reading
    EXPECT_FALSE(filter.matches("s/xa-b"));
    EXPECT_TRUE(filter.matches("s/xa"));
}

TEST(NameFilter, NamesWhatCannotParse) {
    NameFilter filter;
    std::string error;
    EXPECT_FALSE(NameFilter::parse("s/arm\\", filter, error));
    EXPECT_NE(error.find("a '\\' at the end of 's/arm\\'"), std::string::npos) << error;
    EXPECT_NE(error.find("'arm/*\\-fast' for a literal '-'"), std::string::npos) << error;
    EXPECT_FALSE(NameFilter::parse("s/a::b", filter, error));
    EXPECT_NE(error.find("an empty pattern at column 5 of 's/a::b'"), std::string::npos) << error;
}

TEST(Selection, AFilterThatIsATestIdAsWrittenSelectsThatTestAlone) {
    SuiteSpec suite;
    suite.name = "arm-suite";
    suite.tests = {test("arm-fast [x] #2", {}), test("arm", {}), test("arm-fast", {})};
    for (const std::string id : {"arm-suite/arm-fast [x] #2", "arm-suite/arm"}) {
        std::vector<SuiteSpec> suites{suite};
        Selection selection;
        NameFilter filter;
        std::string error;
        ASSERT_TRUE(NameFilter::parse(id, filter, error)) << error;
        selection.filters.push_back(std::move(filter));
        applySelection(suites, selection);
        ASSERT_EQ(suites.size(), 1u) << id;
        ASSERT_EQ(suites[0].tests.size(), 1u) << id;
        EXPECT_EQ("arm-suite/" + suites[0].tests[0].name, id);
    }
}

TEST(Selection, AnExactIdWinsOverPatternSyntax) {
    SuiteSpec suite;
    suite.name = "arm::left";
    suite.tests = {test("grip", {}), test("grip-", {}), test("other", {})};
    for (const std::string id : {"arm::left/grip", "arm::left/grip-"}) {
        std::vector<SuiteSpec> suites{suite};
        NameFilter filter;
        std::string error;
        ASSERT_FALSE(NameFilter::parse(id, filter, error)) << id;
        Selection selection;
        selection.filters.push_back(NameFilter::exactIdOnly(id, error));
        EXPECT_EQ(filterNamingNoTest(suites, selection), "") << id;
        applySelection(suites, selection);
        ASSERT_EQ(suites.size(), 1u) << id;
        ASSERT_EQ(suites[0].tests.size(), 1u) << id;
        EXPECT_EQ("arm::left/" + suites[0].tests[0].name, id);
    }
    // No test has that id: the pattern's error stands.
    Selection selection;
    selection.filters.push_back(NameFilter::exactIdOnly("leg::x", "an empty pattern at column 5"));
    const std::string error = filterNamingNoTest({suite}, selection);
    EXPECT_NE(error.find("--filter leg::x: an empty pattern at column 5"), std::string::npos)
        << error;
}

TEST(NameFilter, AQuestionMarkIsOneUtf8Character) {
    NameFilter filter;
    std::string error;
    ASSERT_TRUE(NameFilter::parse("u/?", filter, error)) << error;
    EXPECT_TRUE(filter.matches("u/\xC3\xBC"));          // ü, 2 bytes
    EXPECT_TRUE(filter.matches("u/\xE2\x82\xAC"));      // €, 3 bytes
    EXPECT_TRUE(filter.matches("u/\xF0\x9F\xA4\x96"));  // 🤖, 4 bytes
    EXPECT_FALSE(filter.matches("u/ab"));
    ASSERT_TRUE(NameFilter::parse("u/??", filter, error)) << error;
    EXPECT_FALSE(filter.matches("u/\xC3\xBC"));
    EXPECT_TRUE(filter.matches("u/\xC3\xBCx"));
    ASSERT_TRUE(NameFilter::parse("*?x", filter, error)) << error;
    EXPECT_TRUE(filter.matches("\xC3\xBC\xC3\xBCx"));
    // Bytes that start no well-formed sequence are one character each.
    ASSERT_TRUE(NameFilter::parse("u/??", filter, error)) << error;
    EXPECT_TRUE(filter.matches("u/\xC3x"));
    EXPECT_TRUE(globMatches("l?g", "l\xC3\xB6g"));
}
