// NestedText: a TAP body whose closed subtests are moved into their parent, indented on output.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "reporters/nested_text.h"

using robottestingframework::reporters::NestedText;

TEST(NestedText, IndentsEachLineOfANestedBlockFourSpacesPerLevel) {
    NestedText inner;
    inner += "ok 1 - a\n";
    NestedText middle;
    middle += "# Subtest: inner\n";
    middle.appendNested(std::move(inner));
    middle += "ok 1 - inner\n";
    NestedText outer;
    outer += "TAP\n";
    outer.appendNested(std::move(middle));
    outer += "end\n";
    EXPECT_EQ(outer.str(), "TAP\n    # Subtest: inner\n        ok 1 - a\n    ok 1 - inner\nend\n");
    EXPECT_EQ(inner.size(), 0u);
    EXPECT_EQ(inner.str(), "");
    EXPECT_EQ(outer.size(),
              std::string("TAP\n# Subtest: inner\nok 1 - a\nok 1 - inner\nend\n").size());
}

TEST(NestedText, ALineAppendedInPartsIsIndentedOnce) {
    NestedText inner;
    inner += "ok 1 - a";
    inner += " # SKIP why";
    inner += "\n";
    NestedText outer;
    outer.appendNested(std::move(inner));
    EXPECT_EQ(outer.str(), "    ok 1 - a # SKIP why\n");
}

TEST(NestedText, TruncateTakesBackTheLastPointAcrossPieces) {
    NestedText text;
    text += "ok 1 - kept\n";
    const std::size_t before = text.size();
    // More than a piece holds: the point taken back spans several pieces.
    const std::string big(NestedText::pieceSize - 3, 'x');
    text += "not ok 2 - " + big + "\n";
    text += big;
    text += "\n";
    text.truncate(before);
    EXPECT_EQ(text.size(), before);
    EXPECT_EQ(text.str(), "ok 1 - kept\n");
    text += "ok 2 - again\n";
    EXPECT_EQ(text.str(), "ok 1 - kept\nok 2 - again\n");
}

TEST(NestedText, TextOverAPieceIsWrittenWholeAndIndented) {
    NestedText inner;
    std::string expected;
    for (int i = 0; i < 3000; ++i) {
        const std::string line = "ok " + std::to_string(i) + " - " + std::string(40, 'n') + "\n";
        inner += line;
        expected += "    " + line;
    }
    NestedText outer;
    outer.appendNested(std::move(inner));
    EXPECT_EQ(outer.str(), expected);
}

TEST(NestedText, AMarksLinesAreWrittenWhereItWasAtTheDepthOfItsBlock) {
    NestedText inner;
    inner += "ok 1 - a\n  ---\n  measurements:\n";
    inner.markLines(7);
    inner += "  ...\nok 2 - b\n";
    inner.markLines(8);  // taken back with its point
    const std::size_t kept = inner.size();
    inner += "not ok 3 - c\n  measurements:\n";
    inner.markLines(9);
    inner.truncate(kept);
    NestedText outer;
    outer += "TAP\n";
    outer.markLines(5);
    outer.appendNested(std::move(inner));
    robottestingframework::reporters::WholeReportText text;
    outer.writeTo(text, [](std::uint64_t id, std::string& lines) {
        lines += "    - id: " + std::to_string(id) + "\n";
    });
    EXPECT_EQ(text.take(),
              "TAP\n    - id: 5\n"
              "    ok 1 - a\n      ---\n      measurements:\n        - id: 7\n      ...\n"
              "    ok 2 - b\n        - id: 8\n");
    EXPECT_EQ(outer.str(),
              "TAP\n    ok 1 - a\n      ---\n      measurements:\n      ...\n"
              "    ok 2 - b\n");
}
