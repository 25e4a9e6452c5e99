#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "core/not_run_reasons.h"
#include "core/text_safety.h"
#include "core_test_helpers.h"

using namespace rtf_test;
using Lines = std::vector<std::string>;

namespace {

struct SuiteRun {
    TestResult result;
    TestResultCollector collector;
    SuiteRun() { result.addListener(&collector); }
    const SuiteRecord& suite() { return collector.suites().at(0); }
    const TestRecord& test(std::size_t i) { return suite().tests.at(i); }
};

class NamedGate : public TestGate {
public:
    explicit NamedGate(std::string name) : name_(std::move(name)) {}
    bool skip(const Test* test, TestMessage& reason) override {
        if (test->getName() != name_) {
            return false;
        }
        reason = TestMessage("skipped: depends on a failed test");
        return true;
    }

private:
    std::string name_;
};

}  // namespace

TEST(TestSuite, FixturesSetUpInOrderAndTornDownInReverse) {
    std::vector<std::string> log;
    LoggingFixture a("a", log), b("b", log);
    LambdaTest t("t", [&] { log.push_back("test"); });
    TestSuite suite("s");
    suite.addFixtureManager(&a);
    suite.addFixtureManager(&b);
    suite.addTest(&t);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_EQ(log, (Lines{"setup a", "setup b", "test", "tearDown b", "tearDown a"}));
    EXPECT_TRUE(suite.succeeded());
    EXPECT_TRUE(r.suite().succeeded());
}

// RTF 2.x's layout: the param's words only, the first one in argv[0], split by RTF 2.x's rules
// (double quotes group, a single quote is a character of its word).
TEST(TestSuite, FixtureSetupGetsItsParamWordsWithTheFirstInArgvZero) {
    std::vector<std::string> log;
    LoggingFixture a("sim", log);
    a.setParam("--from \"sim world.ini\" robot's");
    TestSuite suite("s");
    suite.addFixtureManager(&a);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_EQ(a.args, (Lines{"--from", "sim world.ini", "robot's"}));
}

TEST(TestSuite, SuiteBecomesTheDispatcherOfAFixtureWithoutOne) {
    std::vector<std::string> log;
    LoggingFixture a("a", log);
    TestSuite suite("s");
    suite.addFixtureManager(&a);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_EQ(a.getDispatcher(), &suite);
    EXPECT_EQ(a.getResult(), &r.result);
    EXPECT_EQ(a.getOwner(), &suite);
}

TEST(TestSuite, AddingAFixtureMakesTheSuiteItsDispatcherAtOnce) {
    std::vector<std::string> log;
    LoggingFixture a("a", log);
    TestSuite suite("s");
    suite.addFixtureManager(&a);
    EXPECT_EQ(a.getDispatcher(), &suite);  // before any run, as RTF 2.x's tests check
}

TEST(TestSuite, FailingFixtureTearsDownTheOnesAlreadyUpAndSkipsEveryTest) {
    std::vector<std::string> log;
    LoggingFixture a("a", log), b("b", log), c("c", log);
    b.setupResult = false;
    LambdaTest t1("t1"), t2("t2");
    TestSuite suite("s");
    suite.addFixtureManager(&a);
    suite.addFixtureManager(&b);
    suite.addFixtureManager(&c);
    suite.addTest(&t1);
    suite.addTest(&t2);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_EQ(log, (Lines{"setup a", "setup b", "tearDown a"}));
    EXPECT_TRUE(t1.log.empty());
    EXPECT_FALSE(suite.succeeded());
    ASSERT_EQ(r.suite().tests.size(), 2u);
    EXPECT_EQ(r.test(1).status, TestStatus::Skipped);
    // The reason is said once, by the suite's error; each skipped test refers to it in a line.
    // ...with the first line of the reason, so that a test read alone says why.
    EXPECT_EQ(r.test(0).reason()->message.toString(),
              "the suite's fixture failed (see the suite's error): fixture b failed: setup "
              "returned false");
    EXPECT_EQ(r.test(1).reason()->message.toString(),
              "the suite's fixture failed (see the suite's error): fixture b failed: setup "
              "returned false");
    EXPECT_TRUE(r.suite().fixtureFailed);
    EXPECT_TRUE(
        contains(eventLines(r.collector), "error s: fixture b failed: setup returned false"));
    EXPECT_EQ(r.collector.failedSuiteCount(), 1u);
}

TEST(TestSuite, FixtureThrowingInSetupIsAFixtureFailureWithTheReason) {
    std::vector<std::string> log;
    LoggingFixture a("a", log);
    a.throwInSetup = true;
    LambdaTest t1("t1");
    TestSuite suite("s");
    suite.addFixtureManager(&a);
    suite.addTest(&t1);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_EQ(r.test(0).status, TestStatus::Skipped);
    EXPECT_EQ(r.test(0).reason()->message.toString(),
              "the suite's fixture failed (see the suite's error): fixture a failed: boom");
    EXPECT_EQ(suite.fixtureFailure().getMessage(), "fixture a failed: boom");
    EXPECT_TRUE(contains(eventLines(r.collector), "error s: fixture a failed: boom"));
}

// The first line of a long reason is cut at 200 bytes, between two UTF-8 characters.
TEST(TestSuite, ASkippedTestsReasonIsCutBetweenCharacters) {
    std::string reason;
    for (int i = 0; i < 150; ++i) {
        reason += "\xc3\xa9";  // 'e' with an acute accent, 2 bytes
    }
    const TestMessage said = notrun::fixtureReason(notrun::fixtureFailed,
                                                   TestMessage(" " + reason + "\nthe log's tail"));
    const std::string prefix = std::string(notrun::fixtureFailed) + ":  ";
    ASSERT_EQ(said.getMessage().rfind(prefix, 0), 0u) << said.getMessage();
    const std::string cut = said.getMessage().substr(prefix.size());
    // 1 space and 99 whole characters (199 bytes), not 1 space, 99 and a half.
    EXPECT_EQ(cut, reason.substr(0, 198) + "...");
    EXPECT_EQ(reporters::validUtf8(cut), cut);
}

TEST(TestSuite, FailingTestFailsTheSuite) {
    LambdaTest t1("t1", [] { ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("x"); }), t2("t2");
    TestSuite suite("s");
    suite.addTest(&t1);
    suite.addTest(&t2);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_FALSE(suite.succeeded());
    EXPECT_EQ(r.test(1).status, TestStatus::Passed);  // the others still run
}

TEST(TestSuite, CheckFalseBeforeATestCollapsesTheSuite) {
    std::vector<std::string> log;
    LoggingFixture a("a", log);
    a.checkResult = false;
    LambdaTest t1("t1"), t2("t2");
    TestSuite suite("s");
    suite.addFixtureManager(&a);
    suite.addTest(&t1);
    suite.addTest(&t2);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_TRUE(t1.log.empty());
    EXPECT_EQ(r.test(0).status, TestStatus::Skipped);
    EXPECT_EQ(r.test(1).status, TestStatus::Skipped);
    EXPECT_TRUE(
        contains(eventLines(r.collector), "error s: fixture collapsed: fixture a: check failed"));
    EXPECT_EQ(log.back(), "tearDown a");
    EXPECT_FALSE(suite.succeeded());
}

TEST(TestSuite, CollapseFromAnotherThreadInterruptsTheTestAndSkipsTheRest) {
    TestSuite suite("s");
    std::atomic<bool> sawInterrupt{false};
    LambdaTest* self = nullptr;
    LambdaTest t1("t1", [&] {
        std::thread watcher([&] { suite.fixtureCollapsed(TestMessage("simulator died")); });
        watcher.join();
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        while (!self->interrupted() && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        sawInterrupt = self->interrupted();
    });
    self = &t1;
    LambdaTest t2("t2");
    suite.addTest(&t1);
    suite.addTest(&t2);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_TRUE(sawInterrupt);
    EXPECT_TRUE(t2.log.empty());
    EXPECT_EQ(r.test(0).status, TestStatus::Interrupted);
    EXPECT_EQ(r.test(1).status, TestStatus::Skipped);
    EXPECT_EQ(r.test(1).reason()->message.toString(),
              "the suite's fixture collapsed (see the suite's error): simulator died");
    EXPECT_TRUE(contains(eventLines(r.collector), "error s: fixture collapsed: simulator died"));
    EXPECT_FALSE(suite.succeeded());
    EXPECT_EQ(suite.fixtureFailure().getMessage(), "simulator died");
}

TEST(TestSuite, CollapseIsReportedOnceAfterTheRunningTestEnds) {
    TestSuite suite("s");
    LambdaTest t1("t1", [&] {
        suite.fixtureCollapsed(TestMessage("first"));
        suite.fixtureCollapsed(TestMessage("second"));
    });
    suite.addTest(&t1);
    SuiteRun r;
    suite.run(r.result);
    const Lines lines = eventLines(r.collector);
    EXPECT_EQ(lines,
              (Lines{"start-suite s", "start-test t1", "interrupted t1: stopped while running",
                     "end-test t1", "error s: fixture collapsed: first", "end-suite s"}));
}

TEST(TestSuite, CriticalErrorSkipsTheRestOfTheSuite) {
    LambdaTest t1("t1", [] { ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL("robot fell"); });
    LambdaTest t2("t2"), t3("t3");
    TestSuite suite("s");
    suite.addTest(&t1);
    suite.addTest(&t2);
    suite.addTest(&t3);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_TRUE(t2.log.empty());
    EXPECT_EQ(r.test(1).status, TestStatus::Skipped);
    EXPECT_EQ(r.test(2).status, TestStatus::Skipped);
    EXPECT_EQ(r.test(1).reason()->message.getMessage(), "critical error in t1: robot fell");
}

TEST(TestSuite, SkipRemainingSkipsTheTestsAfterTheCurrentOne) {
    TestSuite suite("s");
    LambdaTest t1("t1", [&] { suite.skipRemaining(TestMessage("no more")); }), t2("t2");
    suite.addTest(&t1);
    suite.addTest(&t2);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_EQ(r.test(0).status, TestStatus::Passed);
    EXPECT_EQ(r.test(1).status, TestStatus::Skipped);
}

TEST(TestSuite, GateSkipsTheTestItRefuses) {
    NamedGate gate("t2");
    LambdaTest t1("t1"), t2("t2"), t3("t3");
    TestSuite suite("s");
    suite.addTest(&t1);
    suite.addTest(&t2);
    suite.addTest(&t3);
    suite.setGate(&gate);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_TRUE(t2.log.empty());
    EXPECT_EQ(r.test(1).status, TestStatus::Skipped);
    EXPECT_EQ(r.test(1).reason()->message.getMessage(), "skipped: depends on a failed test");
    EXPECT_EQ(r.test(2).status, TestStatus::Passed);
    EXPECT_TRUE(suite.succeeded());
}

TEST(TestSuite, InterruptDuringATestReportsTheRestInterrupted) {
    TestSuite suite("s");
    LambdaTest t1("t1", [&] { suite.interrupt(); }), t2("t2");
    suite.addTest(&t1);
    suite.addTest(&t2);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_EQ(r.test(0).status, TestStatus::Interrupted);
    EXPECT_EQ(r.test(1).status, TestStatus::Interrupted);
    EXPECT_TRUE(t2.log.empty());
    EXPECT_FALSE(suite.succeeded());
}

TEST(TestSuite, ReportNotRunReportsEveryTestWithTheReason) {
    LambdaTest t1("t1"), t2("t2");
    TestSuite suite("s");
    suite.addTest(&t1);
    suite.addTest(&t2);
    SuiteRun r;
    suite.reportNotRun(r.result, TestMessage("shard 2 only"), false);
    EXPECT_EQ(eventLines(r.collector),
              (Lines{"start-suite s", "start-test t1", "skipped t1: shard 2 only", "end-test t1",
                     "start-test t2", "skipped t2: shard 2 only", "end-test t2", "end-suite s"}));
}

TEST(TestSuite, RemoveTestAndSize) {
    LambdaTest t1("t1"), t2("t2");
    TestSuite suite("s");
    suite.addTest(&t1);
    suite.addTest(&t2);
    suite.removeTest(&t1);
    ASSERT_EQ(suite.size(), 1u);
    EXPECT_EQ(suite.tests()[0], &t2);
    suite.reset();
    EXPECT_EQ(suite.size(), 0u);
}

TEST(TestSuite, FixtureWatcherThreadReportsWhileTheTestReports) {
    // A fixture watching the world from its own thread: reports, then the world collapses.
    class Watcher : public FixtureManager {
    public:
        bool setup(int, char**) override {
            thread_ = std::thread([this] {
                while (!testStarted) {
                    std::this_thread::yield();
                }
                for (int i = 0; i < 200; ++i) {
                    ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("world ok");
                }
                getDispatcher()->fixtureCollapsed(TestMessage("world gone"));
            });
            return true;
        }
        void tearDown() override { thread_.join(); }
        std::atomic<bool> testStarted{false};

    private:
        std::thread thread_;
    } watcher;
    watcher.setName("watcher");
    TestSuite suite("s");
    LambdaTest* self = nullptr;
    LambdaTest t1("t1", [&] {
        watcher.testStarted = true;
        for (int i = 0; i < 200; ++i) {
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("test ok");
        }
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        while (!self->interrupted() && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    });
    self = &t1;
    suite.addFixtureManager(&watcher);
    suite.addTest(&t1);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_EQ(r.suite().events.size(), 201u);  // 200 reports and the collapse
    EXPECT_EQ(r.test(0).events.size(), 201u);  // 200 reports and the interruption
    EXPECT_FALSE(suite.succeeded());
}

// A fixture that says why before its setup returns false: the skipped tests carry what it said.
TEST(TestSuite, WhatAFixtureReportedBeforeFailingIsTheReasonOfTheSkippedTests) {
    std::vector<std::string> log;
    struct Reporting : LoggingFixture {
        using LoggingFixture::LoggingFixture;
        bool setup(int argc, char** argv) override {
            LoggingFixture::setup(argc, argv);
            ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("no robot on the bus");
            return false;
        }
    } fixture("bus", log);
    LambdaTest t("t");
    TestSuite suite("s");
    suite.addFixtureManager(&fixture);
    suite.addTest(&t);
    SuiteRun r;
    suite.run(r.result);
    ASSERT_EQ(r.suite().tests.size(), 1u);
    // What it reported is in the suite's error, said once; the skipped test refers to it.
    EXPECT_EQ(r.test(0).reason()->message.toString(),
              "the suite's fixture failed (see the suite's error): fixture bus failed: setup "
              "returned false after reporting: no robot on the bus");
    EXPECT_TRUE(contains(
        eventLines(r.collector),
        "error s: fixture bus failed: setup returned false after reporting: no robot on the bus"));
}

TEST(TestSuite, FixtureThrowingFixtureExceptionFailsTheSuiteWithItsMessage) {
    // RTF 2.x fixtures throw FixtureException when the world cannot be set up.
    class ThrowingFixture : public FixtureManager {
    public:
        bool setup(int, char**) override {
            throw FixtureException(TestMessage("the simulator did not start"));
        }
    } fixture;
    fixture.setName("sim");
    LambdaTest t1("t1");
    TestSuite suite("s");
    suite.addFixtureManager(&fixture);
    suite.addTest(&t1);
    SuiteRun r;
    suite.run(r.result);
    EXPECT_TRUE(r.suite().fixtureFailed);
    EXPECT_EQ(r.test(0).status, TestStatus::Skipped);
    EXPECT_NE(suite.fixtureFailure().getMessage().find("the simulator did not start"),
              std::string::npos)
        << suite.fixtureFailure().getMessage();
}

TEST(TestSuite, Rtf2ListenerOverridingTheTestFormsHearsTheSuite) {
    // RTF 2.x's TestListener passed the suite as a `const Test*`; listeners override that form.
    class Rtf2Listener : public TestListener {
    public:
        void startTestSuite(const robottestingframework::Test* test) override {
            heard.push_back("start " + test->getName());
        }
        void endTestSuite(const robottestingframework::Test* test) override {
            heard.push_back("end " + test->getName());
        }
        std::vector<std::string> heard;
    } listener;
    LambdaTest t1("t1");
    TestSuite suite("s");
    suite.addTest(&t1);
    TestResult result;
    result.addListener(&listener);
    suite.run(result);
    EXPECT_EQ(listener.heard, (Lines{"start s", "end s"}));
}

namespace {

// A fixture whose tear-down finds something wrong with its world and says it as a record.
class CheckingFixture : public FixtureManager {
public:
    void tearDown() override {
        Attachment log;
        log.path = "rtf-attachments/1-server.log";
        log.description = "log of process server";
        taken = getDispatcher()->fixtureCheckFailed(
            "world 'lab': stop of 'server'", TestMessage("'server' exited with status 1"), &log);
    }
    bool taken = false;
};

}  // namespace

TEST(TestSuite, AFailedCheckOfAFixtureTearDownIsARecordOfItsOwnAfterTheTests) {
    TestSuite suite("lab");
    CheckingFixture fixture;
    suite.addFixtureManager(&fixture);
    LambdaTest only("only");
    suite.addTest(&only);
    SuiteRun run;
    suite.run(run.result);
    EXPECT_TRUE(fixture.taken);
    EXPECT_FALSE(suite.succeeded());
    ASSERT_EQ(run.suite().tests.size(), 2u);
    EXPECT_EQ(run.test(0).name, "only");
    EXPECT_EQ(run.test(0).status, TestStatus::Passed);
    const TestRecord& record = run.test(1);
    EXPECT_EQ(record.name, "world 'lab': stop of 'server'");
    EXPECT_EQ(record.status, TestStatus::Failed);
    ASSERT_EQ(record.events.size(), 2u);
    EXPECT_EQ(record.events[0].message.getMessage(), "'server' exited with status 1");
    ASSERT_TRUE(record.events[1].attachment);
    EXPECT_EQ(record.events[1].attachment->path, "rtf-attachments/1-server.log");
    // Not also an error of the suite itself.
    EXPECT_TRUE(run.suite().events.empty());
}

TEST(TestSuite, ADispatcherOfItsOwnMayRefuseAFixtureCheck) {
    // FixtureEvents' default: not taken, so the fixture says it otherwise.
    class Collapses : public FixtureEvents {
    public:
        void fixtureCollapsed(TestMessage) override {}
    } collapses;
    EXPECT_FALSE(collapses.fixtureCheckFailed("x", TestMessage("y"), nullptr));
}
