// The TAP parser against the rules of the TAP 14 specification (testanything.org/tap-version-14
// -specification.html), one row per rule: the stream, and the verdict a harness must reach.
// Written from the specification's rules and examples, not copied from it.
#include <gtest/gtest.h>

#include <string>

#include "languages/exec/tap_parser.h"

using robottestingframework::languages::parseTap;
using robottestingframework::languages::TapStream;

namespace {

struct Rule {
    const char* name;
    const char* stream;
    bool failed;           // the harness's verdict
    std::size_t points;    // test points read, every level
    std::size_t failures;  // points that count as failures
    const char* problem;   // part of the one problem expected; "" for none
    const char* bailOut;   // the bail out's reason; nullptr when the stream does not bail out
};

void PrintTo(const Rule& rule, std::ostream* out) {
    *out << rule.name;
}

const Rule rules[] = {
    {"PlanFirst", "TAP version 14\n1..2\nok 1 - a\nok 2 - b\n", false, 2, 0, "", nullptr},
    {"PlanLast", "TAP version 14\nok 1 - a\nnot ok 2 - b\n1..2\n", true, 2, 1, "", nullptr},
    {"NoNumbers", "TAP version 14\n1..2\nok\nok\n", false, 2, 0, "", nullptr},
    {"MissingPlan", "TAP version 14\nok 1\n", true, 1, 0, "no plan", nullptr},
    {"PlanNotMet", "TAP version 14\n1..3\nok 1\nok 2\n", true, 2, 0, "planned 3 test(s) but ran 2",
     nullptr},
    // "Test points may be output in any order": out of order is valid and successful.
    {"NumbersOutOfOrder", "TAP version 14\n1..4\nok 1\nok 3\nok 2\nok 4\n", false, 4, 0, "",
     nullptr},
    // ...but a number the plan does not hold is an error (tap-parser says so too).
    {"NumberBeyondThePlan", "TAP version 14\n1..2\nok 1\nok 3\n", true, 2, 0,
     "test number 3 is beyond the plan 1..2", nullptr},
    // "Harnesses must not treat failing SKIP test points as a test failure".
    {"FailingSkipIsNoFailure", "TAP version 14\n1..2\nok 1\nnot ok 2 # SKIP no camera\n", false, 2,
     0, "", nullptr},
    {"FailingSkipAnyCase", "TAP version 14\n1..1\nnot ok 1 - x # skipped: off\n", false, 1, 0, "",
     nullptr},
    // A failing TODO point is expected to fail.
    {"FailingTodoIsNoFailure", "TAP version 14\n1..1\nnot ok 1 - walks # TODO later\n", false, 1, 0,
     "", nullptr},
    {"PassingTodoPasses", "TAP version 14\n1..1\nok 1 - walks # TODO later\n", false, 1, 0, "",
     nullptr},
    {"SkipAll", "TAP version 14\n1..0 # SKIP no robot\n", false, 0, 0, "", nullptr},
    // "Bail out!": the words are case-insensitive; the reason may escape '#' and '\'.
    {"BailOut", "TAP version 14\n1..2\nok 1\nBail out! gone\nok 2\n", true, 1, 0, "", "gone"},
    {"BailOutLowerCase", "TAP version 14\n1..2\nok 1\nbail out! gone\n", true, 1, 0, "", "gone"},
    {"BailOutUpperCase", "TAP version 14\n1..2\nBAIL OUT!\n", true, 0, 0, "", ""},
    {"BailOutReasonUnescaped", "TAP version 14\n1..1\nBail out! fuse \\# 3 \\\\ 4\n", true, 0, 0,
     "", "fuse # 3 \\ 4"},
    // Lines that are not TAP are kept as output; they never fail a stream.
    {"TextBetweenPoints", "TAP version 14\n1..2\nok 1\nwarming up\nok 2\n", false, 2, 0, "",
     nullptr},
    {"Comments", "TAP version 14\n# starting\n1..1\nok 1 # a comment is no directive\n", false, 1,
     0, "", nullptr},
    {"Pragma", "TAP version 14\npragma +strict\n1..1\nok 1\n", false, 1, 0, "", nullptr},
    // YAML diagnostics: two spaces deeper than their point, between --- and ....
    {"YamlBlock", "TAP version 14\n1..1\nnot ok 1\n  ---\n  got: 2\n  want: 3\n  ...\n", true, 1, 1,
     "", nullptr},
    {"TextInsideYaml", "TAP version 14\n1..2\nok 1\n  ---\n  a: 1\nprinted\n  ...\nok 2\n", false,
     2, 0, "", nullptr},
    {"PointEndsAnOpenYaml", "TAP version 14\n1..2\nok 1\n  ---\n  a: 1\nok 2\n", false, 2, 0, "",
     nullptr},
    {"YamlOpenAtTheEnd", "TAP version 14\n1..1\nok 1\n  ---\n  a: 1\n", true, 1, 0,
     "YAML block not closed", nullptr},
    // Subtests: indented four spaces, ended by the parent's point.
    {"Subtest",
     "TAP version 14\n1..1\n    # Subtest: arm\n    1..2\n    ok 1\n    ok 2\nok 1 - arm\n", false,
     3, 0, "", nullptr},
    {"SubtestNamedOutside",
     "TAP version 14\n1..1\n# Subtest: arm\n    1..1\n    ok 1\nok 1 - arm\n", false, 2, 0, "",
     nullptr},
    {"FailingSubtest",
     "TAP version 14\n1..1\n    # Subtest: arm\n    1..1\n    not ok 1\nnot ok 1 - arm\n", true, 2,
     2, "", nullptr},
    {"SubtestPlanNotMet", "TAP version 14\n1..1\n    1..2\n    ok 1\nok 1 - arm\n", true, 2, 0,
     "subtest 'subtest': planned 2 test(s) but ran 1", nullptr},
    {"TextInsideASubtest",
     "TAP version 14\n1..1\n# Subtest: arm\n    1..2\n    ok 1\nlogging\n# note\n    ok 2\nok 1\n",
     false, 3, 0, "", nullptr},
    {"NestedSubtests",
     "TAP version 14\n1..1\n    1..1\n        1..1\n        ok 1\n    ok 1\nok 1\n", false, 3, 0,
     "", nullptr},
    {"StraySubtestComment", "TAP version 14\n1..1\n# Subtest: nothing\nok 1\n", false, 1, 0, "",
     nullptr},
    // Choices stricter than the reference parser (README: "TAP from exec tests").
    {"TwoPlans", "TAP version 14\n1..1\nok 1\n1..1\n", true, 1, 0, "more than one plan", nullptr},
    {"PlanInTheMiddle", "TAP version 14\nok 1\n1..2\nok 2\n", true, 2, 0,
     "the plan must come before the first test or after the last", nullptr},
    {"PointsAfterSkipAll", "TAP version 14\n1..0 # SKIP off\nok 1\n", true, 1, 0,
     "planned 0 test(s) but ran 1", nullptr},
    {"UnsupportedVersion", "TAP version 15\n1..1\nok 1\n", true, 1, 0, "unsupported", nullptr},
    // Not TAP at all: plain output, judged by the exit status instead.
    {"NotTap", "hello\nworld\n", false, 0, 0, "", nullptr},
};

class Tap14Rules : public ::testing::TestWithParam<Rule> {};

TEST_P(Tap14Rules, GivesTheSpecificationsVerdict) {
    const Rule& rule = GetParam();
    const TapStream tap = parseTap(rule.stream);
    EXPECT_EQ(tap.failed(), rule.failed);
    EXPECT_EQ(tap.points.size(), rule.points);
    std::size_t failures = 0;
    for (const auto& point : tap.points) {
        failures += point.failed() ? 1 : 0;
    }
    EXPECT_EQ(failures, rule.failures);
    if (rule.problem[0] == '\0') {
        EXPECT_TRUE(tap.problems.empty()) << tap.problems.front().message;
    } else {
        ASSERT_EQ(tap.problems.size(), 1u);
        EXPECT_NE(tap.problems[0].message.find(rule.problem), std::string::npos)
            << tap.problems[0].message;
    }
    EXPECT_EQ(tap.bailedOut, rule.bailOut != nullptr);
    if (rule.bailOut != nullptr) {
        EXPECT_EQ(tap.bailOutReason, rule.bailOut);
    }
}

INSTANTIATE_TEST_SUITE_P(Specification, Tap14Rules, ::testing::ValuesIn(rules),
                         [](const ::testing::TestParamInfo<Rule>& info) {
                             return std::string(info.param.name);
                         });

TEST(Tap14Rules, TextInsideASubtestStaysOutput) {
    const TapStream tap =
        parseTap("TAP version 14\n1..1\n# Subtest: arm\n    1..1\nlogging\n    ok 1\nok 1\n");
    ASSERT_EQ(tap.otherText.size(), 1u);
    EXPECT_EQ(tap.otherText[0], "logging");
    ASSERT_EQ(tap.points.size(), 2u);
    EXPECT_EQ(tap.points[0].subtest, "arm");
}

TEST(Tap14Rules, AStraySubtestCommentInsideASubtestNamesNothing) {
    // Unindented inside "arm": a comment, which neither ends "arm" nor names a level.
    const TapStream tap = parseTap(
        "TAP version 14\n1..1\n# Subtest: arm\n    1..2\n    ok 1\n# Subtest: stray\n    ok 2\n"
        "ok 1 - arm\n");
    EXPECT_TRUE(tap.problems.empty()) << tap.problems.front().message;
    ASSERT_EQ(tap.points.size(), 3u);
    EXPECT_EQ(tap.points[0].subtest, "arm");
    EXPECT_EQ(tap.points[1].subtest, "arm");
    EXPECT_EQ(tap.points[2].subtest, "");
    ASSERT_EQ(tap.comments.size(), 1u);
    EXPECT_EQ(tap.comments[0], "Subtest: stray");
}

TEST(Tap14Rules, TheOlderFormNamesTheSubtestBeforeIt) {
    // node --test: "# Subtest: arm" outside, then the subtest's own points' names inside.
    const TapStream tap = parseTap(
        "TAP version 13\n# Subtest: arm\n    # Subtest: moves\n    ok 1 - moves\n    1..1\n"
        "ok 1 - arm\n1..1\n");
    EXPECT_TRUE(tap.problems.empty());
    ASSERT_EQ(tap.points.size(), 2u);
    EXPECT_EQ(tap.points[0].subtest, "arm");
}

TEST(Tap14Rules, TextInsideYamlIsOutputAndTheBlockGoesOn) {
    const TapStream tap =
        parseTap("TAP version 14\n1..1\nnot ok 1\n  ---\n  a: 1\nprinted\n  b: 2\n  ...\n");
    ASSERT_EQ(tap.points.size(), 1u);
    EXPECT_EQ(tap.points[0].diagnostics, "a: 1\nb: 2\n");
    ASSERT_EQ(tap.otherText.size(), 1u);
    EXPECT_EQ(tap.otherText[0], "printed");
}

}  // namespace
