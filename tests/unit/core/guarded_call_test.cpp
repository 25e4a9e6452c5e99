#include "core/guarded_call.h"

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include <robottestingframework/Exception.h>
#include <robottestingframework/TestMessage.h>

using robottestingframework::guardedCall;
using robottestingframework::TestErrorException;
using robottestingframework::TestMessage;

TEST(GuardedCall, ACallThatReturnsIsNoFailure) {
    std::string why = "untouched";
    EXPECT_TRUE(guardedCall([] {}, why));
    EXPECT_EQ(why, "untouched");
}

// A process fixture's failure quotes the last lines of a world process's log, which may hold a
// NUL byte: what() ended the reason there and the rest of the story was lost.
TEST(GuardedCall, AnRtfExceptionsMessageIsKeptWholePastANulByte) {
    const std::string text = std::string("before \0 after", 14) + "\n  | READY";
    std::string why;
    EXPECT_FALSE(guardedCall([&] { throw TestErrorException(TestMessage(text)); }, why));
    EXPECT_EQ(why, text);
}

TEST(GuardedCall, TheSourceLocationFollowsTheMessageAsWhatSaysIt) {
    const TestMessage message("broke", "", "fixture.cpp", 12);
    std::string why;
    EXPECT_FALSE(guardedCall([&] { throw TestErrorException(message); }, why));
    EXPECT_EQ(why, TestErrorException(message).what());
}

TEST(GuardedCall, OtherExceptionsGiveWhatAndUnknownOnesSaySo) {
    std::string why;
    EXPECT_FALSE(guardedCall([] { throw std::runtime_error("plain"); }, why));
    EXPECT_EQ(why, "plain");
    EXPECT_FALSE(guardedCall([] { throw 42; }, why));
    EXPECT_EQ(why, "unhandled exception of unknown type");
}
