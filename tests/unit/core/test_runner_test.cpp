#include <gtest/gtest.h>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>

#include "core_test_helpers.h"

using namespace rtf_test;
using Lines = std::vector<std::string>;

namespace {

class SkipAll : public TestGate {
public:
    bool skip(const Test* test, TestMessage& reason) override {
        asked.push_back(test->getName());
        reason = TestMessage("not selected");
        return true;
    }
    std::vector<std::string> asked;
};

}  // namespace

TEST(TestRunner, RunsTestsAndSuitesInOrderBetweenStartAndEnd) {
    LambdaTest t1("t1"), t2("t2");
    TestSuite suite("s");
    suite.addTest(&t2);
    TestRunner runner;
    runner.addTest(&t1);
    runner.addTest(&suite);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    runner.run(result);
    EXPECT_EQ(eventLines(collector),
              (Lines{"start-runner ", "start-test t1", "end-test t1", "start-suite s",
                     "start-test t2", "end-test t2", "end-suite s", "end-runner "}));
}

TEST(TestRunner, InterruptStopsTheCurrentTestAndReportsTheRestInterrupted) {
    TestRunner runner;
    LambdaTest t1("t1", [&] { runner.interrupt(); }), t2("t2");
    TestSuite suite("s");
    LambdaTest t3("t3");
    suite.addTest(&t3);
    runner.addTest(&t1);
    runner.addTest(&t2);
    runner.addTest(&suite);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    runner.run(result);
    EXPECT_TRUE(runner.interrupted());
    EXPECT_TRUE(t2.log.empty());
    EXPECT_TRUE(t3.log.empty());
    EXPECT_EQ(collector.countOf(TestStatus::Interrupted), 3u);
    // The message says what happened, not the kind's word again ("interrupted: interrupted").
    EXPECT_TRUE(contains(eventLines(collector),
                         "interrupted t3: not run: the run was stopped before it started"));
    EXPECT_TRUE(contains(eventLines(collector),
                         "interrupted t2: not run: the run was stopped before it started"));
    EXPECT_EQ(collector.suiteCount(), 1u);
}

TEST(TestRunner, GateSkipsTestsAndWholeSuites) {
    LambdaTest t1("t1"), t2("t2");
    TestSuite suite("s");
    suite.addTest(&t2);
    TestRunner runner;
    runner.addTest(&t1);
    runner.addTest(&suite);
    SkipAll gate;
    runner.setGate(&gate);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    runner.run(result);
    EXPECT_TRUE(t1.log.empty());
    EXPECT_TRUE(t2.log.empty());
    EXPECT_EQ(collector.skippedCount(), 2u);
    EXPECT_EQ(gate.asked, (Lines{"t1", "s"}));
}

TEST(TestRunner, GateIsPassedDownToSuites) {
    struct SkipT2 : TestGate {
        bool skip(const robottestingframework::Test* test, TestMessage& reason) override {
            reason = TestMessage("no");
            return test->getName() == "t2";
        }
    } gate;
    LambdaTest t1("t1"), t2("t2");
    TestSuite suite("s");
    suite.addTest(&t1);
    suite.addTest(&t2);
    TestRunner runner;
    runner.addTest(&suite);
    runner.setGate(&gate);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    runner.run(result);
    EXPECT_FALSE(t1.log.empty());
    EXPECT_TRUE(t2.log.empty());
}

TEST(TestRunner, RemoveTestAndReset) {
    LambdaTest t1("t1"), t2("t2");
    TestRunner runner;
    runner.addTest(&t1);
    runner.addTest(&t2);
    runner.removeTest(&t1);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    runner.run(result);
    EXPECT_TRUE(t1.log.empty());
    EXPECT_EQ(collector.testCount(), 1u);
    runner.reset();
    TestResultCollector again;
    result.removeListener(&collector);
    result.addListener(&again);
    runner.run(result);
    EXPECT_EQ(again.testCount(), 0u);
    EXPECT_EQ(collector.testCount(), 1u);
}
