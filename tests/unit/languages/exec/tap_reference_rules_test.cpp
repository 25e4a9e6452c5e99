// The TAP parser against the rules of npm's tap-parser (the reference TAP consumer) where TAP 14
// leaves them open: "pragma +strict", plans that do not start at 1, a point number given twice,
// and what makes a plan line. One row per rule, in this project's words; the cases are ours, not
// tap-parser's fixtures (README: "TAP from exec tests" gives the corpus figure).
#include <gtest/gtest.h>

#include <string>

#include "languages/exec/tap_parser.h"

using robottestingframework::languages::parseTap;
using robottestingframework::languages::TapStream;

namespace {

struct Rule {
    const char* name;
    const char* stream;
    bool failed;          // the verdict
    const char* problem;  // part of the first problem expected; "" for none
};

void PrintTo(const Rule& rule, std::ostream* out) {
    *out << rule.name;
}

const Rule rules[] = {
    // pragma +strict: a line that is not TAP fails the stream, from the pragma on.
    {"StrictRefusesText", "TAP version 14\npragma +strict\n1..1\nwarming up\nok 1\n", true,
     "a line that is not TAP, under pragma +strict: 'warming up'"},
    {"TextBeforeStrictIsFine", "TAP version 14\nwarming up\npragma +strict\n1..1\nok 1\n", false,
     ""},
    {"StrictOffAgain", "TAP version 14\npragma +strict\npragma -strict\n1..1\nwarming up\nok 1\n",
     false, ""},
    {"CommentsAreTapUnderStrict", "TAP version 14\npragma +strict\n1..1\n# a note\nok 1\n", false,
     ""},
    {"StrictReachesASubtest",
     "TAP version 14\npragma +strict\n1..1\n    1..1\n    arm moved\n    ok 1\nok 1\n", true,
     "subtest 'subtest': a line that is not TAP"},
    {"OtherPragmasChangeNothing", "TAP version 14\npragma +bail\n1..1\nhello\nok 1\n", false, ""},
    // TAP 12 has no version line: under strict, "TAP version 12" is a line that is not TAP.
    {"Version12LineUnderStrict", "pragma +strict\nTAP version 12\n1..1\nok 1\n", true,
     "TAP 12 has no version line"},
    {"Version12LineWithoutStrict", "TAP version 12\n1..1\nok 1\n", false, ""},
    // A plan N..M: the points numbered N to M, M - N + 1 of them.
    {"PlanFromFive", "TAP version 14\n5..7\nok 5\nok 6\nok 7\n", false, ""},
    {"PlanFromFiveAtTheEnd", "TAP version 14\nok 5\nok 6\n5..6\n", false, ""},
    {"PlanFromFiveCountsThePoints", "TAP version 14\n5..7\nok 5\nok 6\n", true,
     "planned 3 test(s) but ran 2"},
    {"NumberBeforeThePlansStart", "TAP version 14\n1..2\nok 0\nok 2\n", true,
     "test number 0 is before the plan 1..2"},
    {"NumberBeforeAnOffsetPlan", "TAP version 14\n3..4\nok 2\nok 4\n", true,
     "test number 2 is before the plan 3..4"},
    // A plan whose end comes before its start is no plan (and 1..0 is the skip-all one).
    {"BackwardsPlanIsText", "TAP version 14\n9..2\n1..1\nok 1\n", false, ""},
    {"BackwardsPlanUnderStrict", "TAP version 14\npragma +strict\n9..2\n1..1\nok 1\n", true,
     "a line that is not TAP, under pragma +strict: '9..2'"},
    // A plan line is the numbers, and then nothing or " # comment": not even a trailing space.
    {"PlanWithATrailingSpace", "TAP version 14\n1..2 \nok 1\nok 2\n", true, "malformed plan"},
    {"PlanWithWordsAfter", "TAP version 14\n1..2 tests\nok 1\nok 2\n", true, "malformed plan"},
    {"PlanWithAComment", "TAP version 14\n1..2 # two moves\nok 1\nok 2\n", false, ""},
    // A number given twice: the count may match the plan, and yet a point is missing.
    {"NumberGivenTwice", "TAP version 14\n1..3\nok 1\nok 2\nok 2\n", true,
     "test number 2 is given more than once"},
    {"NumberGivenTwiceWithoutAPlanAhead", "TAP version 14\nok 1\nok 1\n1..2\n", true,
     "test number 1 is given more than once"},
    {"UnnumberedPointsAreNoRepeats", "TAP version 14\n1..2\nok\nok\n", false, ""},
    {"SameNumberInTwoSubtests",
     "TAP version 14\n1..2\n    1..1\n    ok 1\nok 1\n    1..1\n    ok 1\nok 2\n", false, ""},
};

class TapReferenceRules : public ::testing::TestWithParam<Rule> {};

TEST_P(TapReferenceRules, GivesTheReferenceParsersVerdict) {
    const Rule& rule = GetParam();
    const TapStream tap = parseTap(rule.stream);
    EXPECT_EQ(tap.failed(), rule.failed);
    if (rule.problem[0] == '\0') {
        EXPECT_TRUE(tap.problems.empty()) << tap.problems.front().message;
    } else {
        ASSERT_FALSE(tap.problems.empty());
        EXPECT_NE(tap.problems[0].message.find(rule.problem), std::string::npos)
            << tap.problems[0].message;
    }
}

INSTANTIATE_TEST_SUITE_P(TapParser, TapReferenceRules, ::testing::ValuesIn(rules),
                         [](const ::testing::TestParamInfo<Rule>& info) {
                             return std::string(info.param.name);
                         });

TEST(TapReferenceRules, RepeatsAreToldWithinABoundedMemory) {
    // Numbers far apart: the ones past the budget are not tracked, and nothing grows unbounded.
    std::string stream = "TAP version 14\n";
    for (unsigned long n : {1ul, 4000000000ul, 4000000000ul, 2ul, 2ul}) {
        stream += "ok " + std::to_string(n) + "\n";
    }
    stream += "1..5\n";
    const TapStream tap = parseTap(stream);
    ASSERT_FALSE(tap.problems.empty());
    EXPECT_NE(tap.problems[0].message.find("test number 2 is given more than once"),
              std::string::npos)
        << tap.problems[0].message;
}

}  // namespace
