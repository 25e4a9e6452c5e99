#include <chrono>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <robottestingframework/Exception.h>
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>

#include "core_test_helpers.h"

using namespace rtf_test;

namespace {

class Named : public Test {
public:
    explicit Named(std::string name) : Test(std::move(name)) {}
    void run(TestResult&) override {}
    bool succeeded() const override { return true; }
};

// Sends one test with the given outcome events to the collector.
void oneTest(TestResultCollector& c, const Test& t,
             std::initializer_list<ResultEvent::Kind> outcomes) {
    using Kind = ResultEvent::Kind;
    c.startTest(&t);
    for (Kind kind : outcomes) {
        const TestMessage msg(std::string(toString(kind)) + " message");
        switch (kind) {
            case Kind::Failure:
                c.addFailure(&t, msg);
                break;
            case Kind::Error:
                c.addError(&t, msg);
                break;
            case Kind::Crash:
                c.addCrash(&t, msg);
                break;
            case Kind::Timeout:
                c.addTimeout(&t, msg);
                break;
            case Kind::Interrupted:
                c.addInterrupted(&t, msg);
                break;
            case Kind::Skipped:
                c.addSkipped(&t, msg);
                break;
            case Kind::Report:
                c.addReport(&t, msg);
                break;
            default:
                break;
        }
    }
    c.endTest(&t);
}

TestStatus statusOf(std::initializer_list<ResultEvent::Kind> outcomes) {
    TestResultCollector c;
    Named t("t");
    oneTest(c, t, outcomes);
    return c.suites().at(0).tests.at(0).status;
}

}  // namespace

using Kind = ResultEvent::Kind;

TEST(TestResultCollector, StatusIsTheHighestOutcome) {
    EXPECT_EQ(statusOf({}), TestStatus::Passed);
    EXPECT_EQ(statusOf({Kind::Report}), TestStatus::Passed);
    EXPECT_EQ(statusOf({Kind::Skipped}), TestStatus::Skipped);
    EXPECT_EQ(statusOf({Kind::Skipped, Kind::Failure}), TestStatus::Failed);
    EXPECT_EQ(statusOf({Kind::Failure, Kind::Error}), TestStatus::Error);
    EXPECT_EQ(statusOf({Kind::Error, Kind::Crash}), TestStatus::Crashed);
    EXPECT_EQ(statusOf({Kind::Crash, Kind::Timeout}), TestStatus::TimedOut);
    EXPECT_EQ(statusOf({Kind::Timeout, Kind::Interrupted, Kind::Failure}), TestStatus::Interrupted);
}

TEST(TestResultCollector, ReasonIsTheFirstEventOfTheDecidingKind) {
    TestResultCollector c;
    Named t("t");
    c.startTest(&t);
    c.addFailure(&t, TestMessage("f1"));
    c.addError(&t, TestMessage("e1"));
    c.addError(&t, TestMessage("e2"));
    c.endTest(&t);
    EXPECT_EQ(c.suites()[0].tests[0].reason()->message.getMessage(), "e1");
}

TEST(TestResultCollector, CountsEveryState) {
    TestResultCollector c;
    Named a("a"), b("b"), d("d"), e("e"), f("f");
    oneTest(c, a, {});
    oneTest(c, b, {Kind::Failure});
    oneTest(c, d, {Kind::Skipped});
    oneTest(c, e, {Kind::Crash});
    oneTest(c, f, {Kind::Timeout});
    EXPECT_EQ(c.testCount(), 5u);
    EXPECT_EQ(c.passedCount(), 1u);
    EXPECT_EQ(c.failedCount(), 3u);
    EXPECT_EQ(c.skippedCount(), 1u);
    EXPECT_EQ(c.countOf(TestStatus::Crashed), 1u);
}

TEST(TestResultCollector, TestsOutsideASuiteGoToAnUnnamedSuiteRecord) {
    TestResultCollector c;
    Named a("a");
    oneTest(c, a, {});
    ASSERT_EQ(c.suites().size(), 1u);
    EXPECT_EQ(c.suites()[0].name, "");
    EXPECT_EQ(c.suites()[0].tests[0].name, "a");
    EXPECT_EQ(c.suiteCount(), 0u);
}

TEST(TestResultCollector, SuiteRecordsHoldTheirTestsAndOwnEvents) {
    TestResultCollector c;
    TestSuite s("s");
    Named a("a");
    c.startTestSuite(&s);
    c.addReport(&s, TestMessage("fixture up"));
    oneTest(c, a, {Kind::Report});
    c.addError(&s, TestMessage("fixture collapsed"));
    c.endTestSuite(&s);
    ASSERT_EQ(c.suites().size(), 1u);
    const SuiteRecord& suite = c.suites()[0];
    EXPECT_EQ(suite.name, "s");
    ASSERT_EQ(suite.events.size(), 2u);
    EXPECT_EQ(suite.tests.at(0).events.size(), 1u);
    EXPECT_TRUE(suite.fixtureFailed);
    EXPECT_FALSE(suite.succeeded());
    EXPECT_EQ(c.suiteCount(), 1u);
    EXPECT_EQ(c.failedSuiteCount(), 1u);
    EXPECT_EQ(c.passedSuiteCount(), 0u);
}

TEST(TestResultCollector, EventsAreInOrderWithIncreasingTimes) {
    TestResultCollector c;
    Named a("a");
    c.startTestRunner();
    oneTest(c, a, {Kind::Report});
    c.endTestRunner();
    const auto& events = c.getResults();
    ASSERT_EQ(events.size(), 5u);
    EXPECT_EQ(events[0].kind, Kind::StartRunner);
    EXPECT_EQ(events[2].kind, Kind::Report);
    EXPECT_EQ(events[2].testName, "a");
    for (std::size_t i = 1; i < events.size(); ++i) {
        EXPECT_GE(events[i].time, events[i - 1].time);
    }
    EXPECT_GE(c.duration(), 0.0);
}

TEST(TestResultCollector, DurationIsEndMinusStart) {
    TestResultCollector c;
    Named a("a");
    oneTest(c, a, {});
    const auto& events = c.getResults();
    EXPECT_DOUBLE_EQ(c.suites()[0].tests[0].duration, events[1].time - events[0].time);
}

TEST(TestResultCollector, OutputIsKeptAsTextNotAsEvents) {
    TestResultCollector c;
    Named a("a");
    c.startTest(&a);
    c.addOutput(&a, "line 1\n");
    c.addOutput(&a, "line 2\n");
    c.endTest(&a);
    EXPECT_EQ(c.suites()[0].tests[0].output, "line 1\nline 2\n");
    EXPECT_TRUE(c.suites()[0].tests[0].events.empty());
}

TEST(TestResultCollector, WithoutKeepingEventsCountsStayAndRecordsAreDropped) {
    TestResultCollector c;
    c.setKeepEvents(false);
    Named a("a");
    for (int i = 0; i < 100; ++i) {
        oneTest(c, a, {i % 2 ? Kind::Failure : Kind::Report});
    }
    EXPECT_TRUE(c.getResults().empty());
    EXPECT_EQ(c.testCount(), 100u);
    EXPECT_EQ(c.failedCount(), 50u);
    ASSERT_EQ(c.suites().size(), 1u);
    EXPECT_EQ(c.suites()[0].tests.size(), 1u);  // the last test only
}

TEST(TestResultCollector, InterruptOpenEndsTheOpenTestAndSuiteAsInterrupted) {
    TestResultCollector c;
    TestSuite suite("s");
    Named done("done");
    Named running("running");
    c.startTestRunner();
    c.startTestSuite(&suite);
    oneTest(c, done, {});
    c.startTest(&running);
    c.interruptOpen(TestMessage("quit"));
    ASSERT_EQ(c.suites().size(), 1u);
    const auto& tests = c.suites()[0].tests;
    ASSERT_EQ(tests.size(), 2u);
    EXPECT_EQ(tests[0].status, TestStatus::Passed);
    EXPECT_EQ(tests[1].status, TestStatus::Interrupted);
    EXPECT_EQ(tests[1].reason()->message.getMessage(), "quit");
    EXPECT_EQ(c.suiteCount(), 1u);
    EXPECT_EQ(c.failedCount(), 1u);
    // Its interrupted test fails the suite: nothing is said of fixtures it may not have.
    EXPECT_TRUE(c.suites()[0].events.empty());
    EXPECT_EQ(c.failedSuiteCount(), 1u);
}

TEST(TestResultCollector, InterruptOpenFailsASuiteWhoseTearDownDidNotFinish) {
    // Every test ended, the fixture's tearDown hung, and the runner quit: not a passed suite.
    TestResultCollector c;
    TestSuite suite("s");
    Named done("done");
    c.startTestRunner();
    c.startTestSuite(&suite);
    oneTest(c, done, {});
    c.interruptOpen(TestMessage("interrupted: the runner quit"));
    ASSERT_EQ(c.suites().size(), 1u);
    const auto& record = c.suites()[0];
    EXPECT_FALSE(record.succeeded());
    EXPECT_TRUE(record.fixtureFailed);
    ASSERT_EQ(record.events.size(), 1u);
    EXPECT_EQ(record.events[0].message.getMessage(),
              "interrupted: the runner quit: the tearDown of the suite's fixtures did not finish");
    EXPECT_EQ(c.failedSuiteCount(), 1u);
    EXPECT_EQ(c.passedSuiteCount(), 0u);

    // Before any test: its set-up did not finish.
    TestResultCollector early;
    early.startTestRunner();
    early.startTestSuite(&suite);
    early.interruptOpen(TestMessage("quit"));
    ASSERT_EQ(early.suites().size(), 1u);
    ASSERT_EQ(early.suites()[0].events.size(), 1u);
    EXPECT_EQ(early.suites()[0].events[0].message.getMessage(),
              "quit: the set-up of the suite's fixtures did not finish");
    EXPECT_EQ(early.failedSuiteCount(), 1u);
}

TEST(TestResult, DispatchesToEveryListenerInOrderAndRemoves) {
    struct Log : TestListener {
        Log(std::string name, std::vector<std::string>& log) : name(std::move(name)), log(log) {}
        void addReport(const robottestingframework::Test*, TestMessage msg) override {
            log.push_back(name + ":" + msg.getMessage());
        }
        std::string name;
        std::vector<std::string>& log;
    };
    std::vector<std::string> log;
    Log first("1", log), second("2", log);
    TestResult result;
    result.addListener(&first);
    result.addListener(&second);
    result.addListener(&first);  // once only
    result.addReport(nullptr, TestMessage("a"));
    result.removeListener(&first);
    result.addReport(nullptr, TestMessage("b"));
    EXPECT_EQ(log, (std::vector<std::string>{"1:a", "2:a", "2:b"}));
}

TEST(TestResultCollector, WithoutKeepingEventsAnEarlierFailureStillFailsTheSuite) {
    TestResultCollector c;
    c.setKeepEvents(false);
    TestSuite s("s");
    Named a("a"), b("b");
    c.startTestSuite(&s);
    oneTest(c, a, {Kind::Failure});
    oneTest(c, b, {});
    c.endTestSuite(&s);
    EXPECT_EQ(c.failedSuiteCount(), 1u);
}

TEST(TestResultCollector, WithoutTheEventLogRecordsStayAndGetResultsIsEmpty) {
    TestResultCollector c;
    c.setKeepEventLog(false);
    Named a("a");
    c.startTest(&a);
    c.addCheck(&a, TestMessage("holds"), true);
    c.addFailure(&a, TestMessage("broken"));
    c.endTest(&a);
    EXPECT_TRUE(c.getResults().empty());
    ASSERT_EQ(c.suites().at(0).tests.size(), 1u);
    const TestRecord& record = c.suites()[0].tests[0];
    EXPECT_EQ(record.status, TestStatus::Failed);
    ASSERT_EQ(record.events.size(), 2u);
    EXPECT_EQ(record.events[0].kind, Kind::Check);
    ASSERT_NE(record.reason(), nullptr);
    EXPECT_EQ(record.reason()->message.getMessage(), "broken");
}

TEST(TestResultCollector, WithoutChecksRecordsKeepEverythingElse) {
    TestResultCollector c;
    c.setKeepChecks(false);
    Named a("a");
    c.startTest(&a);
    c.addCheck(&a, TestMessage("holds"), true);
    c.addCheck(&a, TestMessage("does not hold"), false);
    c.addReport(&a, TestMessage("said"));
    c.endTest(&a);
    const TestRecord& record = c.suites().at(0).tests.at(0);
    ASSERT_EQ(record.events.size(), 1u);
    EXPECT_EQ(record.events[0].kind, Kind::Report);
    EXPECT_EQ(c.getResults().size(), 5u);  // the log, when kept, still has every event
}

TEST(TestResultCollector, ASuiteReservesItsRecordsOnce) {
    TestResultCollector c;
    TestSuite s("s");
    Named a("a"), b("b"), t("t");
    s.addTest(&a);
    s.addTest(&b);
    c.startTestSuite(&s);
    oneTest(c, a, {});
    const TestRecord* first = &c.suites().at(0).tests.at(0);
    oneTest(c, b, {});
    EXPECT_EQ(first, &c.suites()[0].tests[0]);  // not moved by the second record
    oneTest(c, t, {});                          // more than the suite said: still recorded
    c.endTestSuite(&s);
    EXPECT_EQ(c.suites()[0].tests.size(), 3u);
}

TEST(Collector, ResetForgetsEverythingSoTheCollectorServesANewRun) {
    TestResultCollector c;
    Named a("a");
    c.startTestRunner();
    oneTest(c, a, {ResultEvent::Kind::Failure});
    c.endTestRunner();
    ASSERT_EQ(c.testCount(), 1u);
    ASSERT_EQ(c.failedCount(), 1u);

    c.reset();
    EXPECT_EQ(c.testCount(), 0u);
    EXPECT_EQ(c.failedCount(), 0u);
    EXPECT_EQ(c.suiteCount(), 0u);
    EXPECT_TRUE(c.getResults().empty());
    EXPECT_TRUE(c.suites().empty());

    Named b("b");
    oneTest(c, b, {});
    EXPECT_EQ(c.testCount(), 1u);
    EXPECT_EQ(c.passedCount(), 1u);
    ASSERT_EQ(c.suites().size(), 1u);
    EXPECT_EQ(c.suites()[0].tests.at(0).name, "b");
}

TEST(TestId, IsGivenOnceUniqueAndNeverZero) {
    Named a("same");
    Named b("same");
    const std::uint64_t first = a.getId();
    EXPECT_NE(first, 0u);
    EXPECT_EQ(a.getId(), first);
    EXPECT_NE(b.getId(), first);
}

TEST(TestResultCollector, TwoTestsOfOneNameKeepTheirOwnEvents) {
    TestResultCollector c;
    Named first("twin");
    Named second("twin");
    c.startTest(&first);
    c.startTest(&second);
    c.addFailure(&first, TestMessage("first broke"));  // not the innermost: found by id
    c.addReport(&second, TestMessage("second said"));
    c.endTest(&second);
    c.endTest(&first);
    const auto& tests = c.suites().at(0).tests;
    ASSERT_EQ(tests.size(), 2u);
    EXPECT_EQ(tests[0].id, first.getId());
    EXPECT_EQ(tests[0].status, TestStatus::Failed);
    EXPECT_EQ(tests[0].events.at(0).testId, first.getId());
    EXPECT_EQ(tests[1].id, second.getId());
    EXPECT_EQ(tests[1].status, TestStatus::Passed);
    EXPECT_EQ(tests[1].events.at(0).message.getMessage(), "second said");
    EXPECT_EQ(c.failedCount(), 1u);
}

TEST(TestResultCollector, ARenameIsAnEventNotTheNameReadLater) {
    TestResultCollector c;
    TestResult result;
    result.addListener(&c);
    LambdaTest test("before");
    test.body = [&test] { test.setName("during"); };
    test.run(result);
    EXPECT_EQ(c.suites().at(0).tests.at(0).name, "during");
    // Not running any more: the record keeps what the events said.
    test.setName("after");
    EXPECT_EQ(c.suites().at(0).tests.at(0).name, "during");
    // The stand-ins of the runner send it themselves.
    Named standIn("planned");
    c.startTest(&standIn);
    standIn.setName("ignored");  // not running as a TestCase: no event
    result.renameTest(&standIn, "reported");
    c.endTest(&standIn);
    EXPECT_EQ(c.suites().at(0).tests.at(1).name, "reported");
}

TEST(TestResultCollector, AHugeNameIsCutToItsFirst4KiBOnACharacter) {
    TestResultCollector c;
    TestResult result;
    result.addListener(&c);
    LambdaTest test("before");
    // 4095 ASCII bytes, then two-byte characters: byte 4096 is the second of one.
    const std::string huge = std::string(4095, 'n') + [] {
        std::string accents;
        for (int i = 0; i < 500000; ++i) {
            accents += "\xc3\xa9";
        }
        return accents;
    }();
    test.body = [&] { test.setName(huge); };
    test.run(result);
    const std::string& name = c.suites().at(0).tests.at(0).name;
    EXPECT_EQ(name, std::string(4095, 'n') + " [... 1000000 more bytes of this name dropped]");
    EXPECT_EQ(test.getName(), name);
    test.setName(std::string(4096, 'k'));  // up to 4 KiB: whole
    EXPECT_EQ(test.getName(), std::string(4096, 'k'));
}

TEST(TestResultCollector, SeveralRunsAtOnceInOneProcessStayApart) {
    auto run = [](const std::string& name, std::vector<std::string>& names, std::size_t& failed) {
        TestResultCollector collector;
        TestResult result;
        result.addListener(&collector);
        std::vector<std::unique_ptr<LambdaTest>> tests;
        TestSuite suite(name);
        for (int i = 0; i < 50; ++i) {
            tests.push_back(std::make_unique<LambdaTest>("same"));
            LambdaTest* test = tests.back().get();
            test->body = [test, name, i] {
                test->setName(name + std::to_string(i));
                if (i % 2 == 1) {
                    test->failed();
                }
            };
            suite.addTest(test);
        }
        result.startTestRunner();
        suite.run(result);
        result.endTestRunner();
        for (const TestRecord& record : collector.suites().at(0).tests) {
            names.push_back(record.name);
        }
        failed = collector.failedCount();
    };
    std::vector<std::string> left;
    std::vector<std::string> right;
    std::size_t leftFailed = 0;
    std::size_t rightFailed = 0;
    std::thread one(run, "left", std::ref(left), std::ref(leftFailed));
    std::thread two(run, "right", std::ref(right), std::ref(rightFailed));
    one.join();
    two.join();
    ASSERT_EQ(left.size(), 50u);
    ASSERT_EQ(right.size(), 50u);
    for (int i = 0; i < 50; ++i) {
        EXPECT_EQ(left[i], "left" + std::to_string(i));
        EXPECT_EQ(right[i], "right" + std::to_string(i));
    }
    EXPECT_EQ(leftFailed, 25u);
    EXPECT_EQ(rightFailed, 25u);
}

// --retries: a failed attempt followed by a passing one is one flaky test, counted once.
TEST(CollectorRetries, PassingRetryMakesOneFlakyRecord) {
    TestResultCollector c;
    TestSuite suite("s");
    Named t("t");
    c.startTestSuite(&suite);
    oneTest(c, t, {ResultEvent::Kind::Failure});
    c.retryTest(&t, TestMessage("attempt 1 of 2 failed"));
    oneTest(c, t, {});
    c.endTestSuite(&suite);
    ASSERT_EQ(c.suites().size(), 1u);
    ASSERT_EQ(c.suites()[0].tests.size(), 1u);
    const TestRecord& record = c.suites()[0].tests[0];
    EXPECT_EQ(record.status, TestStatus::Flaky);
    ASSERT_EQ(record.attempts.size(), 1u);
    EXPECT_EQ(record.attempts[0].status, TestStatus::Failed);
    EXPECT_EQ(c.testCount(), 1u);
    EXPECT_EQ(c.countOf(TestStatus::Flaky), 1u);
    EXPECT_EQ(c.failedCount(), 0u);
    EXPECT_EQ(c.failedSuiteCount(), 0u);
}

TEST(CollectorRetries, FailingRetriesStayOneFailedRecord) {
    TestResultCollector c;
    TestSuite suite("s");
    Named t("t");
    c.startTestSuite(&suite);
    oneTest(c, t, {ResultEvent::Kind::Failure});
    c.retryTest(&t, TestMessage("again"));
    oneTest(c, t, {ResultEvent::Kind::Crash});
    c.endTestSuite(&suite);
    ASSERT_EQ(c.suites()[0].tests.size(), 1u);
    EXPECT_EQ(c.suites()[0].tests[0].status, TestStatus::Crashed);
    EXPECT_EQ(c.suites()[0].tests[0].attempts.size(), 1u);
    EXPECT_EQ(c.testCount(), 1u);
    EXPECT_EQ(c.failedCount(), 1u);
    EXPECT_EQ(c.failedSuiteCount(), 1u);
}

TEST(CollectorRepetitions, EachRepetitionIsKeyedWithItsOwnStateAndEvents) {
    TestResultCollector c;
    TestResult result;
    result.addListener(&c);
    Named a("a");
    Named b("b");
    result.startTest(&a);
    result.startTest(&b);  // another test open meanwhile does not take a's repetitions
    for (unsigned int k = 1; k <= 3; ++k) {
        result.startRepetition(&a, k, 3);
        if (k == 2) {
            result.addFailure(&a, TestMessage("second fails"));
        }
        result.addReport(&b, TestMessage("b talks"));
    }
    result.endTest(&b);
    result.endTest(&a);

    const TestRecord& ra = c.suites()[0].tests[0];
    ASSERT_EQ(ra.repetitions.size(), 3u);
    EXPECT_EQ(ra.repetitions[0].status, TestStatus::Passed);
    EXPECT_EQ(ra.repetitions[1].status, TestStatus::Failed);
    EXPECT_EQ(ra.repetitions[2].status, TestStatus::Passed);
    EXPECT_EQ(ra.repetitions[1].index, 2u);
    EXPECT_EQ(ra.repetitions[1].count, 3u);
    EXPECT_EQ(ra.status, TestStatus::Failed);
    // The repetition's start is still the report RTF 2.x listeners saw; every event carries it.
    ASSERT_EQ(ra.events.size(), 4u);
    EXPECT_EQ(ra.events[0].message.getMessage(), "repetition 1/3");
    EXPECT_EQ(ra.events[2].message.getMessage(), "second fails");
    EXPECT_EQ(ra.events[2].repetition, 2u);
    EXPECT_EQ(ra.events[3].repetition, 3u);
    EXPECT_EQ(repetitionId(a.getId(), 2), std::to_string(a.getId()) + "#2");

    const TestRecord& rb = c.suites()[0].tests[1];
    EXPECT_TRUE(rb.repetitions.empty());
    for (const ResultEvent& event : rb.events) {
        EXPECT_EQ(event.repetition, 0u);
    }
}

TEST(TestResult, CutsAMessageLongerThan128KiBSayingSo) {
    TestResultCollector c;
    TestResult result;
    result.addListener(&c);
    Named a("a");
    result.startTest(&a);
    result.addFailure(&a, TestMessage(std::string(1000000, 'm'), std::string(10, 'd')));
    result.endTest(&a);
    const ResultEvent& failure = c.suites()[0].tests[0].events.at(0);
    EXPECT_EQ(failure.message.getMessage().compare(0, 131072, std::string(131072, 'm')), 0);
    EXPECT_NE(failure.message.getMessage().find("[... 868928 more bytes of this message dropped]"),
              std::string::npos);
    EXPECT_LT(failure.message.getMessage().size(), 140000u);
    EXPECT_EQ(failure.message.getDetail(), std::string(10, 'd'));
    EXPECT_EQ(c.suites()[0].tests[0].status, TestStatus::Failed);
}

TEST(TestResultCollector, OnceTheOutputBudgetIsSpentEachTestKeepsItsTail) {
    TestResultCollector c;
    c.setOutputBudget(100 * 1024);
    Named a("a");
    Named b("b");
    const std::string chunk(64 * 1024, 'x');
    c.startTest(&a);
    c.addOutput(&a, chunk);
    c.endTest(&a);
    c.startTest(&b);
    c.addOutput(&b, chunk + "the end\n");
    c.endTest(&b);
    const auto& tests = c.suites()[0].tests;
    EXPECT_EQ(tests[0].output, chunk);  // within the budget: whole
    const std::string& cut = tests[1].output;
    EXPECT_LT(cut.size(), 4096u + 200u);
    EXPECT_NE(cut.find("keep 100 KiB of output in all]"), std::string::npos) << cut.substr(0, 200);
    EXPECT_EQ(cut.substr(cut.size() - 8), "the end\n");
}

namespace {

class ThrowingFixture : public FixtureManager {
public:
    bool setup(int, char**) override {
        throw FixtureException(TestMessage("the simulator does not start"));
    }
};

// RTF 2.x's two-suite case: the first suite's fixture throws, its test is not run.
void runTwoSuites(TestResultCollector& collector) {
    LambdaTest test("t");
    ThrowingFixture broken;
    FixtureManager working;
    TestSuite first("first");
    first.addFixtureManager(&broken);
    first.addTest(&test);
    TestSuite second("second");
    second.addFixtureManager(&working);
    second.addTest(&test);
    TestRunner runner;
    runner.addTest(&first);
    runner.addTest(&second);
    TestResult result;
    result.addListener(&collector);
    runner.run(result);
}

}  // namespace

TEST(TestResultCollector, TestsOfASuiteWhoseFixtureFailedAreNotCountedAsInRtf2) {
    TestResultCollector c;
    runTwoSuites(c);
    EXPECT_EQ(c.suiteCount(), 2u);
    EXPECT_EQ(c.passedSuiteCount(), 1u);
    EXPECT_EQ(c.failedSuiteCount(), 1u);
    EXPECT_EQ(c.testCount(), 1u);
    EXPECT_EQ(c.passedCount(), 1u);
    EXPECT_EQ(c.failedCount(), 0u);
    // The records still list it, skipped with the fixture's reason.
    ASSERT_EQ(c.suites().at(0).tests.size(), 1u);
    EXPECT_EQ(c.suites()[0].tests[0].status, TestStatus::Skipped);
}

TEST(TestResultCollector, TheRunnersViewCountsThemAsSkipped) {
    TestResultCollector c;
    c.setCountTestsNotRun(true);
    runTwoSuites(c);
    EXPECT_EQ(c.testCount(), 2u);
    EXPECT_EQ(c.skippedCount(), 1u);
    EXPECT_EQ(c.passedCount(), 1u);
    EXPECT_EQ(c.failedSuiteCount(), 1u);
}

namespace {

// A collector as an RTF 2.x user may extend it: its own handler must still hear every report.
class CountingCollector : public TestResultCollector {
public:
    void addReport(const Test* test, TestMessage msg) override {
        ++reports;
        TestResultCollector::addReport(test, std::move(msg));
    }
    int reports = 0;
};

}  // namespace

TEST(TestResultCollector, KeepsAMeasurementAsACompactRecordWithItsPlaceAmongTheEvents) {
    TestResultCollector c;
    TestResult result;
    result.addListener(&c);
    Named t("measuring");
    result.startTest(&t);
    result.addReport(&t, TestMessage("before"));
    RunEvent event;
    event.test = &t;
    event.data.kind = ResultEvent::Kind::Measurement;
    Measurement rate{"rate", 99.5, "Hz"};
    rate.low = 90;
    event.data.measurement = std::make_shared<const Measurement>(rate);
    event.data.message = TestMessage(describeMeasurement(*event.data.measurement));
    result.publish(event);
    result.addReport(&t, TestMessage("after"));
    result.endTest(&t);
    ASSERT_EQ(c.suites().size(), 1u);
    const TestRecord& test = c.suites()[0].tests.at(0);
    // Not an event of its own in the record (10 000 tests of 3 measurements): a record.
    ASSERT_EQ(test.events.size(), 2u);
    ASSERT_EQ(test.measurements.size(), 1u);
    EXPECT_EQ(test.measurements[0].name(), "rate");
    EXPECT_EQ(test.measurements[0].value, 99.5);
    EXPECT_TRUE(test.measurements[0].hasLow);
    EXPECT_FALSE(test.measurements[0].hasHigh);
    // The reports still list it where it came, as the event it was.
    std::vector<ResultEvent> scratch;
    const std::vector<ResultEvent>& events = test.eventsInOrder(scratch);
    ASSERT_EQ(events.size(), 3u);
    EXPECT_EQ(events[0].message.getMessage(), "before");
    EXPECT_EQ(events[1].kind, ResultEvent::Kind::Measurement);
    EXPECT_EQ(events[1].message.getMessage(), "rate = 99.5 Hz (limits [>= 90] Hz)");
    ASSERT_TRUE(events[1].measurement);
    EXPECT_EQ(events[1].measurement->low, std::optional<double>(90));
    EXPECT_FALSE(events[1].measurement->high);
    EXPECT_TRUE(events[1].passed);
    EXPECT_EQ(events[2].message.getMessage(), "after");
}

TEST(TestResultCollector, MeasurementsOfOneNameAndUnitShareOneLabelAndKeepTheirNumbers) {
    TestResultCollector c;
    TestResult result;
    result.addListener(&c);
    Named first("first");
    Named second("second");
    Measurement error{"tracking error", 0.1, "rad"};
    error.low = -0.25;
    error.high = 1e-07;
    const double values[] = {0.1, 1.0 / 3.0, -2.5e-300};
    for (const Named* test : {&first, &second}) {
        result.startTest(test);
        for (double value : values) {
            error.value = value;
            result.addMeasurement(test, error, error.withinLimits());
        }
        result.addMeasurement(test, Measurement{"rate", 100, "Hz"}, true);
        result.endTest(test);
    }
    const TestRecord& a = c.suites().at(0).tests.at(0);
    const TestRecord& b = c.suites().at(0).tests.at(1);
    ASSERT_EQ(a.measurements.size(), 4u);
    ASSERT_EQ(b.measurements.size(), 4u);
    // One text per (name, unit) for the whole run, not one per measurement.
    EXPECT_EQ(a.measurements[0].label, a.measurements[1].label);
    EXPECT_EQ(a.measurements[0].label, b.measurements[2].label);
    EXPECT_EQ(a.measurements[3].label, b.measurements[3].label);
    EXPECT_NE(a.measurements[0].label, a.measurements[3].label);
    EXPECT_EQ(&a.measurements[0].name(), &b.measurements[1].name());
    for (std::size_t i = 0; i < 3; ++i) {
        const Measurement back = b.measurements[i].measurement();
        EXPECT_EQ(back.name, "tracking error");
        EXPECT_EQ(back.unit, "rad");
        EXPECT_EQ(back.value, values[i]);  // exactly: doubles, not text
        EXPECT_EQ(back.low, std::optional<double>(-0.25));
        EXPECT_EQ(back.high, std::optional<double>(1e-07));
        EXPECT_EQ(b.measurements[i].passed, error.low <= values[i] && values[i] <= 1e-07);
    }
    const Measurement rate = b.measurements[3].measurement();
    EXPECT_EQ(rate.value, 100);
    EXPECT_FALSE(rate.low);
    EXPECT_FALSE(rate.high);
}

TEST(TestResultCollector, ARetriedTestKeepsEachAttemptsMeasurementsApart) {
    TestResultCollector c;
    TestResult result;
    result.addListener(&c);
    Named t("retried");
    result.startTest(&t);
    result.addMeasurement(&t, Measurement{"rate", 1, "Hz"}, true);
    result.addFailure(&t, TestMessage("no"));
    result.endTest(&t);
    result.retryTest(&t, TestMessage("attempt 2"));
    result.startTest(&t);
    result.addMeasurement(&t, Measurement{"rate", 2, "Hz"}, true);
    result.endTest(&t);
    const TestRecord& test = c.suites().at(0).tests.at(0);
    ASSERT_EQ(test.attempts.size(), 1u);
    ASSERT_EQ(test.attempts[0].measurements.size(), 1u);
    EXPECT_EQ(test.attempts[0].measurements[0].value, 1);
    ASSERT_EQ(test.measurements.size(), 1u);
    EXPECT_EQ(test.measurements[0].value, 2);
}

TEST(TestResultCollector, ASubclassStillHearsEachEventThroughItsOwnHandler) {
    CountingCollector c;
    TestResult result;
    result.addListener(&c);
    Named t("reporting");
    result.startTest(&t);
    result.addReport(&t, TestMessage("one"));
    result.addReport(&t, TestMessage("two"));
    result.endTest(&t);
    EXPECT_EQ(c.reports, 2);
    ASSERT_EQ(c.suites().at(0).tests.at(0).events.size(), 2u);
    EXPECT_EQ(c.suites()[0].tests[0].events[1].message.getMessage(), "two");
}

namespace {

double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

RunEvent eventAbout(const Test* test, ResultEvent::Kind kind, const std::string& text,
                    double happened) {
    RunEvent event;
    event.test = test;
    event.data.kind = kind;
    event.data.message = TestMessage(text);
    event.happened = happened;
    return event;
}

// A collector as an RTF 2.x user may extend it, hearing checks and giving its own measurement.
class RescalingCollector : public TestResultCollector {
public:
    void addCheck(const Test* test, TestMessage msg, bool passed) override {
        ++checks;
        TestResultCollector::addCheck(test, std::move(msg), passed);
    }
    void addMeasurement(const Test* test, const Measurement& measurement, bool passed) override {
        Measurement inMillimetres = measurement;
        inMillimetres.value *= 1000;
        inMillimetres.unit = "mm";
        TestResultCollector::addMeasurement(test, inMillimetres, passed);
    }
    int checks = 0;
};

}  // namespace

// A relay (-j N) hands on a suite's events later than they happened: each is timed when it
// happened, whichever thread hands it on; an event given directly is timed when it arrives.
TEST(TestResultCollector, TimesARelayedEventWhenItHappenedAndADirectOneWhenItArrives) {
    const double origin = steadySeconds();  // the collector's clock starts a little later
    TestResultCollector c;
    TestResult result;
    result.addListener(&c);
    Named t("relayed");
    std::thread relay([&] {
        result.publish(eventAbout(&t, ResultEvent::Kind::StartTest, "", origin + 100));
        result.publish(eventAbout(&t, ResultEvent::Kind::Report, "kept a while", origin + 101));
    });
    relay.join();
    result.addReport(&t, TestMessage("direct"));
    result.publish(eventAbout(&t, ResultEvent::Kind::EndTest, "", origin + 102.5));
    const TestRecord& record = c.suites().at(0).tests.at(0);
    EXPECT_NEAR(record.start, 100, 1);
    EXPECT_NEAR(record.duration, 2.5, 0.001);
    ASSERT_EQ(record.events.size(), 2u);
    EXPECT_NEAR(record.events[0].time, 101, 1);
    EXPECT_LT(record.events[1].time, 50);  // now, not the relayed event's time
}

TEST(TestResultCollector, ASubclassHearsEveryCheckEvenThoseTheCollectorDoesNotKeep) {
    RescalingCollector c;
    c.setKeepEventLog(false);
    c.setKeepChecks(false);
    TestResult result;
    result.addListener(&c);
    Named t("checking");
    result.startTest(&t);
    result.addCheck(&t, TestMessage("fine"), true);
    result.addCheck(&t, TestMessage("fine again"), true);
    result.endTest(&t);
    EXPECT_EQ(c.checks, 2);
    EXPECT_TRUE(c.suites().at(0).tests.at(0).events.empty());
}

TEST(TestResultCollector, KeepsTheMeasurementASubclassGivesNotTheOneTheEventCarries) {
    RescalingCollector c;
    TestResult result;
    result.addListener(&c);
    Named t("measuring");
    result.startTest(&t);
    RunEvent event = eventAbout(&t, ResultEvent::Kind::Measurement, "", 0);
    event.data.measurement = std::make_shared<const Measurement>(Measurement{"error", 0.5, "m"});
    result.publish(event);
    result.endTest(&t);
    std::vector<ResultEvent> scratch;
    const std::vector<ResultEvent>& events = c.suites().at(0).tests.at(0).eventsInOrder(scratch);
    ASSERT_EQ(events.size(), 1u);
    ASSERT_NE(events[0].measurement, nullptr);
    EXPECT_EQ(events[0].measurement->value, 500);
    EXPECT_EQ(events[0].measurement->unit, "mm");
    EXPECT_EQ(events[0].message.getMessage(), "error = 500 mm");
}

TEST(TestResultCollector, WithoutChecksKeptAPassedCheckLeavesNoEventAndAFailedOneItsFailure) {
    TestResultCollector c;
    c.setKeepEventLog(false);
    c.setKeepChecks(false);
    TestResult result;
    result.addListener(&c);
    Named t("checking");
    result.startTest(&t);
    result.addCheck(&t, TestMessage("fine", "", "file.cpp", 3), true);
    result.addCheck(&t, TestMessage("broken", "", "file.cpp", 4), false);
    result.addFailure(&t, TestMessage("broken", "", "file.cpp", 4));
    result.endTest(&t);
    const TestRecord& record = c.suites().at(0).tests.at(0);
    ASSERT_EQ(record.events.size(), 1u);
    EXPECT_EQ(record.events[0].kind, ResultEvent::Kind::Failure);
    EXPECT_EQ(record.events[0].message.getSourceLineNumber(), 4u);
    EXPECT_EQ(record.status, TestStatus::Failed);
}
