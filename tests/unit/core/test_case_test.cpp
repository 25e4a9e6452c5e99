#include <future>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include <robottestingframework/Exception.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>

#include "core_test_helpers.h"

using namespace rtf_test;
using Lines = std::vector<std::string>;

namespace {

struct Harness {
    TestResult result;
    TestResultCollector collector;
    Harness() { result.addListener(&collector); }
    const TestRecord& only() { return collector.suites().at(0).tests.at(0); }
};

}  // namespace

TEST(TestCase, PassingTestSendsStartAndEndOnly) {
    Harness r;
    LambdaTest test("t");
    test.run(r.result);
    EXPECT_EQ(eventLines(r.collector), (Lines{"start-test t", "end-test t"}));
    EXPECT_TRUE(test.succeeded());
    EXPECT_EQ(test.log, (Lines{"setup", "run", "tearDown"}));
}

TEST(TestCase, SetupGetsNameAndSplitParam) {
    Harness r;
    LambdaTest test("named");
    test.setParam("--robot \"icub sim\"");
    test.run(r.result);
    EXPECT_EQ(test.args, (Lines{"named", "--robot", "icub sim"}));
}

TEST(TestCase, SetupReturningFalseIsAnErrorAndSkipsRunAndTearDown) {
    Harness r;
    LambdaTest test("t");
    test.onSetup = [] { return false; };
    test.run(r.result);
    EXPECT_EQ(test.log, (Lines{"setup"}));
    EXPECT_FALSE(test.succeeded());
    EXPECT_EQ(r.only().status, TestStatus::Error);
    EXPECT_EQ(r.only().reason()->message.toString(), "setup failed: test t");
}

TEST(TestCase, FailureExceptionInRunIsAFailureAndTearDownStillRuns) {
    Harness r;
    LambdaTest test("t", [] { throw TestFailureException(TestMessage("bad value")); });
    test.run(r.result);
    EXPECT_EQ(test.log, (Lines{"setup", "run", "tearDown"}));
    EXPECT_EQ(r.only().status, TestStatus::Failed);
    EXPECT_EQ(r.only().reason()->message.getMessage(), "bad value");
}

TEST(TestCase, ErrorExceptionIsAnError) {
    Harness r;
    LambdaTest test("t", [] { throw TestErrorException(TestMessage("no robot")); });
    test.run(r.result);
    EXPECT_EQ(r.only().status, TestStatus::Error);
    EXPECT_FALSE(test.hasCriticalError());
}

TEST(TestCase, CriticalErrorIsAnErrorAndMarksTheTest) {
    Harness r;
    LambdaTest test("t", [] { throw TestCriticalErrorException(TestMessage("robot fell")); });
    test.run(r.result);
    EXPECT_EQ(r.only().status, TestStatus::Error);
    ASSERT_TRUE(test.hasCriticalError());
    EXPECT_EQ(test.getCriticalError().getMessage(), "robot fell");
}

TEST(TestCase, StdExceptionIsAnErrorNamingItsTypeAndText) {
    Harness r;
    LambdaTest test("t", [] { throw std::runtime_error("disk full"); });
    test.run(r.result);
    EXPECT_EQ(r.only().status, TestStatus::Error);
    const TestMessage& msg = r.only().reason()->message;
    EXPECT_EQ(msg.getMessage(), "unhandled exception: disk full");
    EXPECT_EQ(msg.getDetail(), "std::runtime_error");
}

TEST(TestCase, ThrowingAnIntIsAnErrorOfUnknownType) {
    Harness r;
    LambdaTest test("t", [] { throw 42; });
    test.run(r.result);
    EXPECT_EQ(r.only().status, TestStatus::Error);
    EXPECT_EQ(r.only().reason()->message.getMessage(), "unhandled exception of unknown type");
    EXPECT_EQ(test.log, (Lines{"setup", "run", "tearDown"}));
}

TEST(TestCase, ExceptionInSetupSkipsRunAndTearDown) {
    Harness r;
    LambdaTest test("t");
    test.onSetup = []() -> bool { throw std::logic_error("no config"); };
    test.run(r.result);
    EXPECT_EQ(test.log, (Lines{"setup"}));
    EXPECT_EQ(r.only().status, TestStatus::Error);
}

TEST(TestCase, ExceptionInTearDownIsReported) {
    Harness r;
    LambdaTest test("t");
    test.onTearDown = [] { throw TestErrorException(TestMessage("cannot park")); };
    test.run(r.result);
    EXPECT_EQ(r.only().status, TestStatus::Error);
    EXPECT_FALSE(test.succeeded());
}

TEST(TestCase, RepetitionRunsNTimesWithAReportEach) {
    Harness r;
    LambdaTest test("t");
    test.setRepetition(3);
    test.run(r.result);
    EXPECT_EQ(test.log, (Lines{"setup", "run", "run", "run", "tearDown"}));
    EXPECT_EQ(eventLines(r.collector),
              (Lines{"start-test t", "report t: repetition 1/3", "report t: repetition 2/3",
                     "report t: repetition 3/3", "end-test t"}));
}

TEST(TestCase, RepetitionStopsAfterAFailureException) {
    Harness r;
    int runs = 0;
    LambdaTest test("t", [&] {
        if (++runs == 2) {
            throw TestFailureException(TestMessage("second run fails"));
        }
    });
    test.setRepetition(5);
    test.run(r.result);
    EXPECT_EQ(runs, 2);
    EXPECT_EQ(test.log.back(), "tearDown");
}

TEST(TestCase, RepetitionGoesOnAfterANonFatalCheck) {
    Harness r;
    int runs = 0;
    LambdaTest test("t", [&] { ROBOTTESTINGFRAMEWORK_TEST_CHECK(++runs != 1, "first fails"); });
    test.setRepetition(3);
    test.run(r.result);
    EXPECT_EQ(runs, 3);
    EXPECT_EQ(r.only().status, TestStatus::Failed);
}

TEST(TestCase, InterruptStopsRepetitionAndReportsInterrupted) {
    Harness r;
    int runs = 0;
    LambdaTest* self = nullptr;
    LambdaTest test("t", [&] {
        if (++runs == 2) {
            self->interrupt();
        }
    });
    self = &test;
    test.setRepetition(10);
    test.run(r.result);
    EXPECT_EQ(runs, 2);
    EXPECT_EQ(r.only().status, TestStatus::Interrupted);
    EXPECT_FALSE(test.succeeded());
    EXPECT_FALSE(test.interrupted());  // reset for the next run
}

TEST(TestCase, FailedWithoutAMessageStillShowsAFailure) {
    Harness r;
    LambdaTest* self = nullptr;
    LambdaTest test("t", [&] { self->failed(); });
    self = &test;
    test.run(r.result);
    EXPECT_FALSE(test.succeeded());
    EXPECT_EQ(r.only().status, TestStatus::Failed);
}

TEST(TestCase, RunningAgainStartsFromACleanState) {
    bool fail = true;
    LambdaTest test("t", [&] {
        if (fail) {
            throw TestCriticalErrorException(TestMessage("x"));
        }
    });
    Harness first;
    test.run(first.result);
    EXPECT_FALSE(test.succeeded());
    fail = false;
    Harness second;
    test.run(second.result);
    EXPECT_TRUE(test.succeeded());
    EXPECT_FALSE(test.hasCriticalError());
    EXPECT_EQ(second.only().status, TestStatus::Passed);
}

TEST(TestCase, CurrentIsTheRunningTestOnlyWhileItRuns) {
    Harness r;
    TestCase* seen = nullptr;
    TestResult* seenResult = nullptr;
    LambdaTest test("t");
    test.body = [&] {
        seen = TestCase::current();
        seenResult = test.getResult();
    };
    test.run(r.result);
    EXPECT_EQ(seen, &test);
    EXPECT_EQ(seenResult, &r.result);
    EXPECT_EQ(TestCase::current(), nullptr);
    EXPECT_EQ(test.getResult(), nullptr);
}

TEST(TestCase, HelperThreadsOfATestReportToIt) {
    Harness r;
    LambdaTest test("t", [] {
        std::thread helper([] { ROBOTTESTINGFRAMEWORK_TEST_REPORT("from a helper thread"); });
        helper.join();
    });
    test.run(r.result);
    EXPECT_TRUE(contains(eventLines(r.collector), "report t: from a helper thread"));
}

// Two runs in two threads of one process (the scheduler's lanes, or two TestRunners): the first
// to end must not take the other's test away from it.
TEST(TestCase, RunsInTwoThreadsEachKeepTheirCurrentTestWhicheverEndsFirst) {
    Harness first;
    Harness second;
    std::promise<void> secondStarted;
    std::promise<void> firstEnded;
    TestCase* seenBySecond = nullptr;
    LambdaTest a("a", [&] { secondStarted.get_future().wait(); });
    LambdaTest b("b", [&] {
        secondStarted.set_value();
        firstEnded.get_future().wait();
        seenBySecond = TestCase::current();
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("after a ended");
    });
    std::thread one([&] {
        a.run(first.result);
        firstEnded.set_value();
    });
    std::thread two([&] { b.run(second.result); });
    one.join();
    two.join();
    EXPECT_EQ(seenBySecond, &b);
    EXPECT_TRUE(contains(eventLines(second.collector), "report b: after a ended"));
    EXPECT_EQ(TestCase::current(), nullptr);
}

TEST(Exception, WhatHasMessageDetailAndLocation) {
    TestFailureException e(TestMessage("value wrong", "x == 2", "motor.cpp", 12));
    EXPECT_STREQ(e.what(), "value wrong: x == 2 (motor.cpp:12)");
    EXPECT_EQ(e.message().getSourceLineNumber(), 12u);
}

TEST(TestStatus, NamesAreStable) {
    EXPECT_STREQ(toString(TestStatus::TimedOut), "timed out");
    EXPECT_STREQ(toString(ResultEvent::Kind::StartRunner), "start-runner");
    EXPECT_TRUE(isFailure(TestStatus::Crashed));
    EXPECT_FALSE(isFailure(TestStatus::Skipped));
}
