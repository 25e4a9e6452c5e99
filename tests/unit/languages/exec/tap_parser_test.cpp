// The TAP parser against a corpus of streams, valid and broken (tests/unit/languages/exec/tap/).
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "build_paths.h"
#include "languages/exec/tap_parser.h"

using robottestingframework::languages::parseTap;
using robottestingframework::languages::TapPoint;
using robottestingframework::languages::TapStream;

namespace {

TapStream parseFile(const std::string& name) {
    std::ifstream file(std::string(build_paths::tapCorpusDir()) + "/" + name);
    EXPECT_TRUE(file.good()) << name;
    std::stringstream text;
    text << file.rdbuf();
    return parseTap(text.str());
}

bool hasProblem(const TapStream& stream, const std::string& part) {
    for (const auto& problem : stream.problems) {
        if (problem.message.find(part) != std::string::npos) {
            return true;
        }
    }
    return false;
}

}  // namespace

TEST(TapParser, ReadsPlanFirst) {
    TapStream tap = parseFile("plan_first.tap");
    EXPECT_TRUE(tap.isTap);
    ASSERT_EQ(tap.points.size(), 3u);
    EXPECT_EQ(tap.points[0].description, "first");
    EXPECT_EQ(tap.points[2].description, "");
    EXPECT_EQ(tap.points[2].number, 3u);
    EXPECT_TRUE(tap.problems.empty());
    EXPECT_FALSE(tap.failed());
}

TEST(TapParser, ReadsPlanLastAndFailingPoint) {
    TapStream tap = parseFile("plan_last.tap");
    ASSERT_EQ(tap.points.size(), 3u);
    EXPECT_FALSE(tap.points[1].ok);
    EXPECT_TRUE(tap.points[1].failed());
    EXPECT_EQ(tap.points[1].line, 2u);
    EXPECT_TRUE(tap.problems.empty());
    EXPECT_TRUE(tap.failed());
}

TEST(TapParser, AttachesYamlDiagnosticsToThePointBefore) {
    TapStream tap = parseFile("v13_yaml.tap");
    EXPECT_EQ(tap.version, 13);
    ASSERT_EQ(tap.points.size(), 2u);
    EXPECT_EQ(tap.points[0].diagnostics, "");
    EXPECT_NE(tap.points[1].diagnostics.find("message: 'joint 3 out of range'"), std::string::npos);
    EXPECT_NE(tap.points[1].diagnostics.find("    indented line"), std::string::npos);
    EXPECT_TRUE(tap.otherText.empty());
    EXPECT_TRUE(tap.problems.empty());
}

TEST(TapParser, ReadsNestedIndentedSubtests) {
    TapStream tap = parseFile("v14_subtests.tap");
    EXPECT_EQ(tap.version, 14);
    ASSERT_EQ(tap.points.size(), 6u);
    EXPECT_EQ(tap.points[0].subtest, "arm > shoulder");
    EXPECT_EQ(tap.points[0].description, "pitch");
    EXPECT_EQ(tap.points[2].subtest, "arm");
    EXPECT_EQ(tap.points[2].description, "shoulder");
    EXPECT_EQ(tap.points[3].subtest, "arm");
    EXPECT_FALSE(tap.points[3].ok);
    EXPECT_NE(tap.points[3].diagnostics.find("message: stuck"), std::string::npos);
    EXPECT_EQ(tap.points[4].subtest, "");
    EXPECT_EQ(tap.points[4].description, "arm");
    EXPECT_TRUE(tap.problems.empty()) << tap.problems[0].message;
}

TEST(TapParser, ReadsOlderSubtestForm) {
    TapStream tap = parseFile("subtest_older_form.tap");
    ASSERT_EQ(tap.points.size(), 4u);
    EXPECT_EQ(tap.points[0].subtest, "camera");
    EXPECT_EQ(tap.points[2].subtest, "");
    EXPECT_TRUE(tap.problems.empty());
    EXPECT_FALSE(tap.failed());
}

TEST(TapParser, HonoursSkipAndTodo) {
    TapStream tap = parseFile("skip_todo.tap");
    ASSERT_EQ(tap.points.size(), 4u);
    EXPECT_EQ(tap.points[0].directive, TapPoint::Directive::Skip);
    EXPECT_EQ(tap.points[0].reason, "no gripper on this robot");
    EXPECT_EQ(tap.points[0].description, "has a gripper");
    EXPECT_EQ(tap.points[1].directive, TapPoint::Directive::Todo);
    EXPECT_FALSE(tap.points[1].failed());
    EXPECT_EQ(tap.points[2].directive, TapPoint::Directive::Todo);
    EXPECT_EQ(tap.points[2].reason, "surprisingly works");
    // TAP 14: a failing SKIP point is no failure (it was not run), as a failing TODO one.
    EXPECT_EQ(tap.points[3].directive, TapPoint::Directive::Skip);
    EXPECT_FALSE(tap.points[3].failed());
    EXPECT_FALSE(tap.failed());
}

TEST(TapParser, ReadsSkipAllPlan) {
    TapStream tap = parseFile("skip_all.tap");
    EXPECT_TRUE(tap.isTap);
    EXPECT_TRUE(tap.skipAll);
    EXPECT_EQ(tap.skipReason, "no robot connected");
    EXPECT_FALSE(tap.failed());
}

TEST(TapParser, StopsAtBailOut) {
    TapStream tap = parseFile("bail_out.tap");
    EXPECT_TRUE(tap.bailedOut);
    EXPECT_EQ(tap.bailOutReason, "lost the connection to the robot");
    EXPECT_EQ(tap.points.size(), 1u);
    EXPECT_TRUE(tap.problems.empty());  // no plan check after a bail out
    EXPECT_TRUE(tap.failed());
}

TEST(TapParser, ReportsPlanMismatch) {
    TapStream tap = parseFile("plan_too_many.tap");
    EXPECT_TRUE(hasProblem(tap, "planned 3 test(s) but ran 2"));
    EXPECT_TRUE(tap.failed());
}

TEST(TapParser, ReportsPlanInTheMiddle) {
    TapStream tap = parseFile("plan_in_middle.tap");
    EXPECT_TRUE(hasProblem(tap, "the plan must come before the first test or after the last"));
}

TEST(TapParser, ReportsMissingPlan) {
    TapStream tap = parseFile("no_plan.tap");
    EXPECT_TRUE(tap.isTap);
    EXPECT_TRUE(hasProblem(tap, "no plan"));
}

TEST(TapParser, ReportsANumberBeyondThePlan) {
    // Out of order is valid TAP 14 (tap14_rules_test.cpp); beyond the plan is not.
    TapStream tap = parseFile("out_of_sequence.tap");
    EXPECT_TRUE(hasProblem(tap, "test number 3 is beyond the plan 1..2"));
    EXPECT_EQ(tap.problems[0].line, 1u);
}

TEST(TapParser, ReportsSecondPlan) {
    EXPECT_TRUE(hasProblem(parseFile("two_plans.tap"), "more than one plan"));
}

TEST(TapParser, ReportsUnclosedYaml) {
    TapStream tap = parseFile("unclosed_yaml.tap");
    EXPECT_TRUE(hasProblem(tap, "YAML block not closed"));
    ASSERT_EQ(tap.points.size(), 1u);
    EXPECT_NE(tap.points[0].diagnostics.find("never closed"), std::string::npos);
}

TEST(TapParser, KeepsEscapedHashInDescription) {
    TapStream tap = parseFile("escaped_hash.tap");
    ASSERT_EQ(tap.points.size(), 2u);
    EXPECT_EQ(tap.points[0].description, "the # sign is text");
    EXPECT_EQ(tap.points[0].directive, TapPoint::Directive::Skip);
    EXPECT_EQ(tap.points[1].directive, TapPoint::Directive::None);
    EXPECT_EQ(tap.points[1].description, "trailing comment # not a directive");
}

TEST(TapParser, RejectsUnsupportedVersion) {
    EXPECT_TRUE(hasProblem(parseFile("unsupported_version.tap"), "unsupported 'TAP version 99'"));
}

TEST(TapParser, LeavesPlainOutputAlone) {
    TapStream tap = parseFile("not_tap.txt");
    EXPECT_FALSE(tap.isTap);
    EXPECT_TRUE(tap.points.empty());
    EXPECT_TRUE(tap.comments.empty());
    ASSERT_EQ(tap.otherText.size(), 3u);
    EXPECT_EQ(tap.otherText[1], "# a comment, not TAP");
    EXPECT_FALSE(tap.failed());
}

TEST(TapParser, SeparatesOutputAndCommentsFromTap) {
    TapStream tap = parseFile("mixed_output.tap");
    EXPECT_TRUE(tap.isTap);
    ASSERT_EQ(tap.otherText.size(), 2u);
    EXPECT_EQ(tap.otherText[0], "connecting to 127.0.0.1");
    ASSERT_EQ(tap.comments.size(), 1u);
    EXPECT_EQ(tap.comments[0], "about to check");
    EXPECT_FALSE(tap.failed());
}

TEST(TapParser, AcceptsCrLfLineEnds) {
    TapStream tap = parseFile("crlf.tap");
    ASSERT_EQ(tap.points.size(), 2u);
    EXPECT_EQ(tap.points[0].description, "crlf");
    EXPECT_TRUE(tap.problems.empty());
}

TEST(TapParser, EmptyStreamIsNotTap) {
    TapStream tap = parseTap("");
    EXPECT_FALSE(tap.isTap);
    EXPECT_FALSE(tap.failed());
}

TEST(TapParser, UnclosedYamlEndsAtALessIndentedLine) {
    // TAP 14: invalid lines should not fail a run; the point keeps what the block said.
    TapStream tap = parseTap("1..2\nnot ok 1 - torque\n  ---\n  message: too high\nok 2 - speed\n");
    EXPECT_TRUE(tap.problems.empty());
    ASSERT_EQ(tap.points.size(), 2u);
    EXPECT_EQ(tap.points[0].diagnostics, "message: too high\n");
    EXPECT_EQ(tap.points[1].description, "speed");
}

TEST(TapParser, BailOutKnowsItsLine) {
    TapStream tap = parseFile("bail_out.tap");
    EXPECT_EQ(tap.bailOutLine, 4u);
}

TEST(TapParser, CutsEndlessLines) {
    std::string stream = "1..1\nok 1 - " + std::string(10 * 1024 * 1024, 'y') + "\n";
    TapStream tap = parseTap(stream);
    ASSERT_EQ(tap.points.size(), 1u);
    EXPECT_LT(tap.points[0].description.size(), 70u * 1024);
    EXPECT_NE(tap.points[0].description.find("more bytes of this line dropped"), std::string::npos);
}

TEST(TapParser, PlainOutputIsNotHeldWithoutBound) {
    // Before any TAP, lines are held back; past 64 KiB the oldest go out as plain text.
    class Counter : public robottestingframework::languages::TapListener {
    public:
        void text(const std::string&) override { ++lines; }
        std::size_t lines = 0;
    } counter;
    robottestingframework::languages::TapParser parser(counter);
    const std::string line = "# " + std::string(98, 'x') + "\n";
    for (int i = 0; i < 10000; ++i) {
        parser.feed(line.data(), line.size());
    }
    EXPECT_GT(counter.lines, 9000u);  // given while the stream goes on, not all at its end
    parser.finish();
    EXPECT_EQ(counter.lines, 10000u);
    EXPECT_FALSE(parser.isTap());
}

TEST(TapParser, TellsPointsAsTheyCome) {
    class Points : public robottestingframework::languages::TapListener {
    public:
        void point(const TapPoint&) override { ++count; }
        int count = 0;
    } points;
    robottestingframework::languages::TapParser parser(points);
    const std::string start = "TAP version 13\n1..3\nok 1 - a\nok 2 - b\n";
    parser.feed(start.data(), start.size());
    EXPECT_EQ(points.count, 1);  // the second may still get a YAML block
    parser.finish();
    EXPECT_EQ(points.count, 2);
    EXPECT_TRUE(parser.failed());  // planned 3
}

namespace {

std::string nestedStream(int depth) {
    std::string text;
    for (int level = 0; level < depth; ++level) {
        text += std::string(4 * level, ' ') + "# Subtest: level\n";
    }
    text += std::string(4 * depth, ' ') + "ok 1 - innermost\n";
    text += std::string(4 * depth, ' ') + "1..1\n";
    for (int level = depth - 1; level >= 0; --level) {
        text += std::string(4 * level, ' ') + "ok 1 - level\n";
        text += std::string(4 * level, ' ') + "1..1\n";
    }
    return text;
}

// The best of several rounds: a machine busy with other work slows some rounds, not all.
double bestParseSeconds(const std::string& text) {
    double best = 1e9;
    for (int round = 0; round < 9; ++round) {
        auto start = std::chrono::steady_clock::now();
        TapStream tap = parseTap(text);
        double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_FALSE(tap.failed());
        best = seconds < best ? seconds : best;
    }
    return best;
}

}  // namespace

TEST(TapParser, NestedSubtestsParseInTimeLinearInTheStream) {
    // Depth 2000 is 16 times the text of depth 500 (each line is indented by its depth).
    // Linear parsing takes about 16 times as long; the former parser took 64 times as long.
    const std::string small = nestedStream(500);
    const std::string large = nestedStream(2000);
    TapStream tap = parseTap(large);
    ASSERT_EQ(tap.points.size(), 2001u);
    EXPECT_EQ(tap.points[0].subtest, "level > level > ... > level > level > level");
    const double ratio = bestParseSeconds(large) / bestParseSeconds(small);
    EXPECT_LT(ratio, 32.0) << "depth 2000 took " << ratio << " times as long as depth 500";
}
