// The measurements and attachments an exec test gives in its TAP YAML diagnostics.
#include <gtest/gtest.h>

#include <cmath>

#include "languages/exec/tap_records.h"

using robottestingframework::TestMessage;
using robottestingframework::languages::readTapRecords;
using robottestingframework::languages::tapDiagnostics;
using robottestingframework::languages::withoutTapRecords;

TEST(TapRecords, ReadsMeasurementsWithAndWithoutLimits) {
    const auto records = readTapRecords(
        "  message: \"fine\"\n"
        "  measurements:\n"
        "    - name: tracking error\n"
        "      value: 0.012\n"
        "      unit: rad\n"
        "      low: 0\n"
        "      high: 0.05\n"
        "    - name: \"loop rate # hz\"\n"
        "      value: 99.5 # a comment\n"
        "  other: 1\n");
    ASSERT_EQ(records.measurements.size(), 2u);
    EXPECT_EQ(records.measurements[0].name, "tracking error");
    EXPECT_EQ(records.measurements[0].value, 0.012);
    EXPECT_EQ(records.measurements[0].unit, "rad");
    EXPECT_EQ(records.measurements[0].low, 0.0);
    EXPECT_EQ(records.measurements[0].high, 0.05);
    EXPECT_EQ(records.measurements[1].name, "loop rate # hz");
    EXPECT_EQ(records.measurements[1].value, 99.5);
    EXPECT_FALSE(records.measurements[1].low);
    EXPECT_TRUE(records.problems.empty());
}

TEST(TapRecords, ReadsAttachmentsAtTheBlocksOwnIndent) {
    const auto records = readTapRecords(
        "attachments:\n"
        "- path: 'it''s.log'\n"
        "  description: the log\n");
    ASSERT_EQ(records.attachments.size(), 1u);
    EXPECT_EQ(records.attachments[0].path, "it's.log");
    EXPECT_EQ(records.attachments[0].description, "the log");
}

TEST(TapRecords, ANonNumberIsAProblemNamingTheItem) {
    const auto records = readTapRecords("measurements:\n  - name: x\n    value: fast\n");
    EXPECT_TRUE(records.measurements.empty());
    ASSERT_EQ(records.problems.size(), 1u);
    EXPECT_EQ(records.problems[0], "measurements item 1: value 'fast' is not a number");
}

TEST(TapRecords, ANumberTooLargeForADoubleIsRefusedAsWritten) {
    const auto records = readTapRecords(
        "measurements:\n  - name: x\n    value: 1e400\n  - name: y\n    value: 2\n"
        "    high: -1e999\n");
    EXPECT_TRUE(records.measurements.empty());
    ASSERT_EQ(records.problems.size(), 2u);
    EXPECT_EQ(records.problems[0],
              "measurements item 1: value '1e400' is too large: a measurement holds at most "
              "1.8e308");
    EXPECT_EQ(records.problems[1],
              "measurements item 2: high '-1e999' is too large: a measurement holds at most "
              "1.8e308");
}

TEST(TapRecords, YamlInfinityIsKeptToBeRefusedByName) {
    const auto records = readTapRecords("measurements:\n  - name: x\n    value: .inf\n");
    ASSERT_EQ(records.measurements.size(), 1u);
    EXPECT_TRUE(std::isinf(records.measurements[0].value));
}

// Issue 38, friction 9: the YAML's measurements and attachments are not pasted in the point's
// text; the other keys are its diagnostics (tapDiagnostics).
TEST(TapRecords, WithoutTapRecordsKeepsOnlyTheOtherKeys) {
    EXPECT_EQ(withoutTapRecords("  message: \"fine\"\n"
                                "  measurements:\n"
                                "    - name: tracking error\n"
                                "      value: 0.012\n"
                                "  other: 1\n"
                                "  attachments:\n"
                                "    - path: plot.svg\n"),
              "  message: \"fine\"\n  other: 1\n");
    EXPECT_EQ(withoutTapRecords("measurements:\n  - name: rate\n    value: 99.5\n"), "");
    EXPECT_EQ(withoutTapRecords("note: fast enough\n"), "note: fast enough\n");
    EXPECT_EQ(withoutTapRecords(""), "");
}

// Issue 38, friction 9: a point's other YAML keys are diagnostics, each key with its value,
// not text pasted after the point's.
TEST(TapRecords, TapDiagnosticsReadsEachTopLevelKey) {
    const TestMessage::Diagnostics found = tapDiagnostics(
        "  message: \"the gripper is open\"\n"
        "  severity: fail\n"
        "  # a comment\n"
        "  got: 3\n"
        "  wanted: 'four'\n"
        "  at:\n"
        "    file: test/gripper.js\n"
        "    line: 12\n"
        "  list:\n"
        "  - a\n"
        "  - b\n"
        "  stack: |\n"
        "    first\n"
        "      second\n"
        "  \"odd key\": x # comment\n"
        "  url: http://h:80/p\n");
    const TestMessage::Diagnostics expected{{"message", "the gripper is open"},
                                            {"severity", "fail"},
                                            {"got", "3"},
                                            {"wanted", "four"},
                                            {"at", "file: test/gripper.js\nline: 12"},
                                            {"list", "- a\n- b"},
                                            {"stack", "first\n  second"},
                                            {"odd key", "x"},
                                            {"url", "http://h:80/p"}};
    EXPECT_EQ(found, expected);
}

TEST(TapRecords, TapDiagnosticsKeepsWhatIsNoKeyWithTheKeyBefore) {
    EXPECT_EQ(tapDiagnostics(""), TestMessage::Diagnostics{});
    EXPECT_EQ(tapDiagnostics("# only a comment\n"), TestMessage::Diagnostics{});
    EXPECT_EQ(tapDiagnostics("- one\n- two\n"),
              (TestMessage::Diagnostics{{"yaml", "- one\n- two"}}));
    EXPECT_EQ(tapDiagnostics("got: 1\nwanted: 2\ngot: 3\n"),
              (TestMessage::Diagnostics{{"got", "3"}, {"wanted", "2"}}));
    EXPECT_EQ(tapDiagnostics("note: a long\n  sentence\nnext: 1\n"),
              (TestMessage::Diagnostics{{"note", "a long\nsentence"}, {"next", "1"}}));
}

TEST(TapRecords, DiagnosticsTextIsOneLinePerKeyAndTheLinesOfABlock) {
    TestMessage message("ok 3 - loop rate");
    message.setDiagnostics({{"note", "fast enough"}, {"at", "file: t.sh\nline: 3"}});
    EXPECT_EQ(message.diagnosticsText(), "note: fast enough\nat:\n  file: t.sh\n  line: 3\n");
    EXPECT_EQ(message.toString(), "ok 3 - loop rate");
}
