// What a world keeper and the runners that use its world say to each other (world_protocol.h),
// and the command line that asks for it (--world-up, --world, --world-down).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "runner/cli/options.h"
#include "runner/cli/world_protocol.h"

using namespace robottestingframework::runner;

TEST(WorldProtocol, RequestsAreKnownByTheirWord) {
    EXPECT_EQ(parseWorldRequest(worldRequestText(WorldRequest::Status)), WorldRequest::Status);
    EXPECT_EQ(parseWorldRequest(worldRequestText(WorldRequest::Down)), WorldRequest::Down);
    EXPECT_EQ(parseWorldRequest("up"), WorldRequest::Unknown);
    EXPECT_EQ(parseWorldRequest(""), WorldRequest::Unknown);
}

TEST(WorldProtocol, AStatusComesBackAsItWasSent) {
    for (auto state : {WorldStatus::State::Starting, WorldStatus::State::Up,
                       WorldStatus::State::Collapsed, WorldStatus::State::Stopping}) {
        WorldStatus sent;
        sent.state = state;
        sent.networkDescriptors = 2;
        sent.reason = "process 'sim' died\n  last lines of its log:\n  | boom";
        sent.suite = "arm reach";
        WorldStatus read;
        ASSERT_TRUE(parseWorldStatus(worldStatusText(sent), read));
        EXPECT_EQ(read.state, state);
        EXPECT_EQ(read.networkDescriptors, 2u);
        EXPECT_EQ(read.reason, sent.reason);
        EXPECT_EQ(read.suite, "arm reach");
    }
}

TEST(WorldProtocol, AStatusNotOfAKeeperIsRefused) {
    WorldStatus status;
    for (const std::string& packet : std::vector<std::string>{
             "", "up 0\n", "rtf-world up\n", "rtf-world up 3\n", "rtf-world sleeping 0\n",
             "rtf-world up x\n", "rtf-world passed\n"}) {
        EXPECT_FALSE(parseWorldStatus(packet, status)) << packet;
    }
}

TEST(WorldProtocol, AnOutcomeCarriesItsText) {
    WorldOutcome read;
    ASSERT_TRUE(parseWorldOutcome(worldOutcomeText({false, "error: tearDown failed\n"}), read));
    EXPECT_FALSE(read.passed);
    EXPECT_EQ(read.text, "error: tearDown failed\n");
    ASSERT_TRUE(parseWorldOutcome(worldOutcomeText({true, ""}), read));
    EXPECT_TRUE(read.passed);
    EXPECT_EQ(read.text, "");
    EXPECT_FALSE(parseWorldOutcome("rtf-world up 0\n", read));
}

TEST(WorldProtocol, TheKeepersFilesAreInItsFolder) {
    EXPECT_EQ(worldSocketPath("/b/w"), "/b/w/keeper.sock");
    EXPECT_EQ(worldLogPath("/b/w"), "/b/w/keeper.log");
    EXPECT_EQ(worldFailedPath("/b/w"), "/b/w/world-failed");
}

TEST(WorldOptions, OneOfTheWorldOptionsAtATime) {
    const char* up[] = {"robottestingframework-testrunner", "--suite", "s.xml", "--world-up", "w"};
    Options options;
    ParseResult result = parseOptions(5, up, options);
    ASSERT_EQ(result.outcome, ParseResult::Outcome::Run) << result.text;
    EXPECT_EQ(options.worldUp, "w");

    const char* both[] = {"robottestingframework-testrunner",
                          "--suite",
                          "s.xml",
                          "--world",
                          "w",
                          "--world-down",
                          "w"};
    Options other;
    result = parseOptions(7, both, other);
    EXPECT_EQ(result.outcome, ParseResult::Outcome::Exit);
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.text.find("one at a time"), std::string::npos) << result.text;
}
