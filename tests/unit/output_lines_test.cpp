// OutputLines: a process's output cut into lines, each kept up to a limit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fixtures/process/output_lines.h"

using robottestingframework::fixtures::OutputLines;

namespace {

struct Collected {
    std::vector<std::string> lines;
    OutputLines::Line add() {
        return [this](const std::string& line) { lines.push_back(line); };
    }
};

}  // namespace

TEST(OutputLines, LinesSplitAnywhereComeOutWhole) {
    OutputLines output(100);
    Collected got;
    for (const char* piece : {"robot ", "up\nsimul", "ator", " ready\r\n", "\n", "tail"}) {
        output.feed(piece, got.add());
    }
    EXPECT_EQ(got.lines, (std::vector<std::string>{"robot up", "simulator ready", ""}));
    EXPECT_EQ(output.partial(), "tail");
    output.finish(got.add());
    EXPECT_EQ(got.lines.back(), "tail");
    EXPECT_EQ(output.partial(), "");
    output.finish(got.add());  // nothing more
    EXPECT_EQ(got.lines.size(), 4u);
}

TEST(OutputLines, ALongLineKeepsItsFirstBytesAndTheNextLineIsWhole) {
    OutputLines output(8);
    Collected got;
    output.feed("0123456789", got.add());
    output.feed(std::string(1 << 20, 'x'), got.add());
    EXPECT_EQ(output.partial(), "01234567");
    output.feed("abc\r\nready\n", got.add());
    EXPECT_EQ(got.lines, (std::vector<std::string>{"01234567", "ready"}));
}

TEST(OutputLines, ALineOfExactlyTheLimitIsKeptWhole) {
    OutputLines output(5);
    Collected got;
    output.feed("ready\nready!\n", got.add());
    EXPECT_EQ(got.lines, (std::vector<std::string>{"ready", "ready"}));
}

TEST(OutputLines, AnUnendedLongLineIsGivenAtTheEnd) {
    OutputLines output(4);
    Collected got;
    output.feed("abcdefgh", got.add());
    EXPECT_TRUE(got.lines.empty());
    output.finish(got.add());
    EXPECT_EQ(got.lines, (std::vector<std::string>{"abcd"}));
}
