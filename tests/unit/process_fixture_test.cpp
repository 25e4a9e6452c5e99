// The process fixture as a suite sees it: set-up failures with their story, reports, collapse.
#include "fixtures/process/process_fixture.h"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/Exception.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestSuite.h>

#include "core_test_helpers.h"
#include "process_test_helpers.h"

using namespace robottestingframework;
using robottestingframework::fixtures::ProcessFixture;
using rtf_process_test::freshFolder;
using rtf_process_test::writeFile;

namespace {

bool contains(const std::string& text, const std::string& words) {
    return text.find(words) != std::string::npos;
}

std::string allEvents(const TestResultCollector& collector) {
    std::string out;
    for (const std::string& line : rtf_test::eventLines(collector)) {
        out += line + "\n";
    }
    return out;
}

class CollapseRecorder : public FixtureEvents {
public:
    void fixtureCollapsed(TestMessage reason) override { reasons.push_back(reason); }
    std::vector<TestMessage> reasons;
};

}  // namespace

TEST(ProcessFixture, ABadWorldFileFailsSetupWithFileAndLine) {
    const auto folder = freshFolder();
    const auto world = writeFile(folder / "world.xml",
                                 "<world>\n  <process name='a' depends='b' command='true'/>\n"
                                 "</world>\n");
    ProcessFixture fixture(world.string());
    ArgumentVector args("");
    try {
        fixture.setup(args.argc(), args.argv());
        FAIL() << "setup did not throw";
    } catch (const TestErrorException& e) {
        EXPECT_TRUE(contains(e.what(), world.string() + ":2: process 'a' depends on 'b'"))
            << e.what();
    }
}

TEST(ProcessFixture, CheckWorldFileReadsItAsTheSetupWouldWithTheParam) {
    // Issue 39, 12: the runner calls it when the plan is made.
    const auto folder = freshFolder();
    const auto world = writeFile(folder / "world.xml",
                                 "<world>\n  <process name='a' command='true'>\n"
                                 "    <ready><port>${port}</port></ready>\n"
                                 "  </process>\n</world>\n");
    EXPECT_EQ(fixtures::checkWorldFile(world.string(), "--var port=8080"), "");
    EXPECT_TRUE(contains(fixtures::checkWorldFile(world.string(), "--var port=http"),
                         world.string() + ":3: 'http' is not a TCP port"));
    EXPECT_TRUE(contains(fixtures::checkWorldFile(world.string(), ""),
                         world.string() + ":3: undefined variable ${port}"))
        << fixtures::checkWorldFile(world.string(), "");
    EXPECT_TRUE(contains(fixtures::checkWorldFile(world.string(), "--colour red"),
                         "unknown option '--colour'"));
    EXPECT_TRUE(contains(fixtures::checkWorldFile((folder / "none.xml").string(), ""),
                         "cannot read the world file"));
}

TEST(ProcessFixture, ParamSetsVariablesAndTheLogFolder) {
    const auto folder = freshFolder();
    const auto world = writeFile(folder / "world.xml",
                                 "<world><process name='a' command=\"/bin/sh -c 'echo "
                                 "${greeting}; exec sleep 30'\"><ready><output>^${greeting}$"
                                 "</output></ready></process></world>");
    ProcessFixture fixture(world.string());
    ArgumentVector args("--var greeting=hello --logdir " + (folder / "mylogs").string());
    ASSERT_TRUE(fixture.setup(args.argc(), args.argv()));
    EXPECT_TRUE(fixture.check());
    fixture.tearDown();
    EXPECT_TRUE(std::filesystem::exists(folder / "mylogs" / "a.log"));

    ArgumentVector wrong("--colour red");
    EXPECT_THROW(fixture.setup(wrong.argc(), wrong.argv()), TestErrorException);
}

TEST(ProcessFixture, TellsTheDispatcherWhenTheWorldCollapses) {
    const auto folder = freshFolder();
    const auto world =
        writeFile(folder / "world.xml",
                  "<world logdir='logs'>\n<process name='robot' command=\"/bin/sh -c 'echo "
                  "ready; sleep 0.2; echo motor fault; exit 2'\">\n"
                  "<ready><output>ready</output></ready></process></world>");
    ProcessFixture fixture(world.string());
    CollapseRecorder recorder;
    fixture.setDispatcher(&recorder);
    ArgumentVector args("");
    ASSERT_TRUE(fixture.setup(args.argc(), args.argv()));
    for (int i = 0; i < 300 && fixture.check(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_FALSE(fixture.check());
    ASSERT_FALSE(recorder.reasons.empty());
    const TestMessage& reason = recorder.reasons.front();
    EXPECT_TRUE(contains(reason.getMessage(), "process 'robot' exited with status 2"))
        << reason.getMessage();
    EXPECT_TRUE(contains(reason.getMessage(), "| motor fault")) << reason.getMessage();
    EXPECT_EQ(reason.getSourceFileName(), world.string());
    EXPECT_EQ(reason.getSourceLineNumber(), 2u);
    fixture.tearDown();
}

TEST(ProcessFixture, InASuiteACollapseSkipsTheRemainingTestsWithTheReason) {
    const auto folder = freshFolder();
    const auto world =
        writeFile(folder / "world.xml",
                  "<world name='lab' logdir='logs'>\n<process name='sim' command=\"/bin/sh -c "
                  "'echo ready; sleep 0.3; echo simulator crashed; exit 1'\">\n"
                  "<ready><output>ready</output></ready></process></world>");
    ProcessFixture fixture(world.string());
    TestSuite suite("with a world");
    suite.addFixtureManager(&fixture);
    // Long enough for the collapse (0.3 s after ready) to be seen on a loaded machine: with
    // 0.8 s the portable job once ran the second test too.
    rtf_test::LambdaTest first("first",
                               [] { std::this_thread::sleep_for(std::chrono::seconds(2)); });
    rtf_test::LambdaTest second("second");
    suite.addTest(&first);
    suite.addTest(&second);

    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    suite.run(result);
    EXPECT_FALSE(suite.succeeded());
    const std::string events = allEvents(collector);
    EXPECT_TRUE(contains(events, "'sim' is ready after")) << events;  // a fixture report
    EXPECT_TRUE(second.log.empty()) << events;                        // never run
    EXPECT_TRUE(contains(events, "process 'sim' exited with status 1")) << events;
    EXPECT_TRUE(contains(events, "simulator crashed")) << events;
    EXPECT_TRUE(contains(events, "stopping 'sim'")) << events;
}

TEST(ProcessFixture, InASuiteASetupFailureSkipsEveryTestWithTheWholeStory) {
    const auto folder = freshFolder();
    const auto world =
        writeFile(folder / "world.xml",
                  "<world logdir='logs'>\n<process name='server' command=\"/bin/sh -c 'echo "
                  "binding; exec sleep 30'\">\n<ready timeout='200ms'>"
                  "<port>1</port></ready></process></world>");
    ProcessFixture fixture(world.string());
    TestSuite suite("no world");
    suite.addFixtureManager(&fixture);
    rtf_test::LambdaTest only("only");
    suite.addTest(&only);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    suite.run(result);
    EXPECT_FALSE(suite.succeeded());
    EXPECT_TRUE(only.log.empty());
    const std::string events = allEvents(collector);
    EXPECT_TRUE(contains(events,
                         "process 'server' did not become ready: TCP port 127.0.0.1:1 "
                         "accepting connections did not happen within 200 ms"))
        << events;
    EXPECT_TRUE(contains(events, "| binding")) << events;
    EXPECT_TRUE(contains(events, "last seen: Connection refused")) << events;
}

// --- Checked shutdowns: each process that does not stop cleanly is a record of its own. -------

namespace {

const TestRecord* recordNamed(const TestResultCollector& collector, const std::string& name) {
    for (const SuiteRecord& suite : collector.suites()) {
        for (const TestRecord& test : suite.tests) {
            if (test.name == name) {
                return &test;
            }
        }
    }
    return nullptr;
}

std::string messages(const TestRecord& record) {
    std::string out;
    for (const ResultEvent& event : record.events) {
        out += std::string(toString(event.kind)) + ": " + event.message.toString() + "\n";
    }
    return out;
}

}  // namespace

TEST(ProcessFixture, InASuiteAProcessThatDoesNotStopCleanlyIsARecordOfItsOwn) {
    const auto folder = freshFolder();
    const auto world = writeFile(
        folder / "world.xml",
        "<world name='lab' logdir='logs'>\n"
        "<process name='server' command=\"/bin/sh -c 'trap &quot;echo saving state; exit "
        "1&quot; INT; echo ready; while :; do sleep 0.02; done'\">\n"
        "<ready><output>ready</output></ready>\n<stop signal='SIGINT' grace='3s'/></process>\n"
        "<process name='clean' command=\"/bin/sh -c 'echo ready; exec sleep 30'\">"
        "<ready><output>ready</output></ready></process></world>");
    ProcessFixture fixture(world.string());
    TestSuite suite("with a world");
    suite.addFixtureManager(&fixture);
    rtf_test::LambdaTest only("only");
    suite.addTest(&only);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    suite.run(result);
    EXPECT_FALSE(suite.succeeded());
    const std::string events = allEvents(collector);
    const TestRecord* test = recordNamed(collector, "only");
    ASSERT_NE(test, nullptr) << events;
    EXPECT_EQ(test->status, TestStatus::Passed);
    // The server's stop, and only its: the clean one has no record.
    const TestRecord* stop = recordNamed(collector, "world 'lab': stop of 'server'");
    ASSERT_NE(stop, nullptr) << events;
    EXPECT_EQ(stop->status, TestStatus::Failed);
    EXPECT_EQ(recordNamed(collector, "world 'lab': stop of 'clean'"), nullptr) << events;
    const std::string said = messages(*stop);
    EXPECT_TRUE(contains(said,
                         "'server' exited with status 1 after SIGINT; a clean stop is: "
                         "status 0 or SIGINT, within 3 s"))
        << said;
    EXPECT_TRUE(contains(said, "| saving state")) << said;  // the last lines of its log
    EXPECT_TRUE(contains(said, "server.log (log of process server)")) << said;  // attached
    // The clean stop is said, as --verbose shows it.
    EXPECT_TRUE(contains(events, "'clean' stopped after")) << events;
    EXPECT_TRUE(contains(events, "(clean)")) << events;
    // Not also a tear-down error of the suite.
    EXPECT_FALSE(contains(events, "tearDown failed")) << events;
}

TEST(ProcessFixture, AProcessThatCollapsedIsNotRecordedAgainWhenTheWorldStops) {
    const auto folder = freshFolder();
    const auto world =
        writeFile(folder / "world.xml",
                  "<world name='lab' logdir='logs'>\n<process name='sim' command=\"/bin/sh -c "
                  "'echo ready; sleep 0.2; exit 1'\">\n"
                  "<ready><output>ready</output></ready></process></world>");
    ProcessFixture fixture(world.string());
    TestSuite suite("with a world");
    suite.addFixtureManager(&fixture);
    rtf_test::LambdaTest first("first",
                               [] { std::this_thread::sleep_for(std::chrono::seconds(2)); });
    suite.addTest(&first);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    suite.run(result);
    EXPECT_FALSE(suite.succeeded());
    const std::string events = allEvents(collector);
    EXPECT_TRUE(contains(events, "process 'sim' exited with status 1")) << events;
    EXPECT_EQ(recordNamed(collector, "world 'lab': stop of 'sim'"), nullptr) << events;
}

TEST(ProcessFixture, WithoutASuiteToTakeTheRecordTheTearDownFailsWithIt) {
    const auto folder = freshFolder();
    const auto world = writeFile(
        folder / "world.xml",
        "<world name='lab' logdir='logs'>\n<process name='stubborn' command=\"/bin/sh -c 'trap "
        "&quot;&quot; TERM; echo ready; while :; do sleep 0.02; done'\">\n"
        "<ready><output>ready</output></ready><stop grace='200ms'/></process></world>");
    ProcessFixture fixture(world.string());
    CollapseRecorder recorder;  // takes collapses only
    fixture.setDispatcher(&recorder);
    ASSERT_TRUE(fixture.setup(0, nullptr));
    try {
        fixture.tearDown();
        FAIL() << "the tear-down should have failed";
    } catch (const TestErrorException& e) {
        const std::string what = e.what();
        EXPECT_TRUE(contains(what,
                             "'stubborn' did not stop within 200 ms of SIGTERM: killed "
                             "with SIGKILL; a clean stop is: status 0 or SIGTERM, within "
                             "200 ms"))
            << what;
    }
}
