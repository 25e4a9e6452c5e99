#include <gtest/gtest.h>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "core_test_helpers.h"

using namespace rtf_test;
using Lines = std::vector<std::string>;

namespace {

// Runs `body` as a test; returns its events, its state and its own record.
struct Outcome {
    Lines events;
    TestStatus status;
    std::vector<ResultEvent> record;
};

Outcome runBody(std::function<void()> body) {
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    LambdaTest test("t", std::move(body));
    test.run(result);
    const TestRecord& record = collector.suites().at(0).tests.at(0);
    return {eventLines(collector), record.status, record.events};
}

}  // namespace

TEST(Assert, TestReportAddsAReportAndPasses) {
    Outcome o = runBody([] { ROBOTTESTINGFRAMEWORK_TEST_REPORT("hello"); });
    EXPECT_TRUE(contains(o.events, "report t: hello"));
    EXPECT_EQ(o.status, TestStatus::Passed);
}

TEST(Assert, TestCheckTrueRecordsAPassedCheck) {
    Outcome o = runBody([] { ROBOTTESTINGFRAMEWORK_TEST_CHECK(1 + 1 == 2, "sum"); });
    ASSERT_EQ(o.record.size(), 1u);
    EXPECT_EQ(o.record[0].kind, ResultEvent::Kind::Check);
    EXPECT_TRUE(o.record[0].passed);
    EXPECT_EQ(o.record[0].message.getDetail(), "1 + 1 == 2");
    EXPECT_EQ(o.status, TestStatus::Passed);
}

TEST(Assert, TestCheckFalseFailsAndTheTestGoesOn) {
    bool after = false;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(false, "nope");
        after = true;
    });
    EXPECT_TRUE(after);
    EXPECT_EQ(o.status, TestStatus::Failed);
    EXPECT_EQ(o.events, (Lines{"start-test t", "check t: nope", "failure t: nope", "end-test t"}));
}

TEST(Assert, TestFailIfTrueFailsOnlyWhenTrueAndGoesOn) {
    bool after = false;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(false, "not this");
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(true, "this");
        after = true;
    });
    EXPECT_TRUE(after);
    EXPECT_EQ(o.events, (Lines{"start-test t", "failure t: this", "end-test t"}));
}

TEST(Assert, TestFailIfFalseFailsOnlyWhenFalseAndGoesOn) {
    bool after = false;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(true, "not this");
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(false, "this");
        after = true;
    });
    EXPECT_TRUE(after);
    EXPECT_EQ(o.events, (Lines{"start-test t", "failure t: this", "end-test t"}));
    EXPECT_EQ(o.record[0].message.getDetail(), "!(false)");
}

TEST(Assert, AsserterTestFailFailsWhenTheConditionDoesNotHoldAsInRtf2) {
    // RTF 2.x's Asserter::testFail(condition, ...): the condition is what should hold.
    Outcome o = runBody([] {
        Asserter::testFail(true, TestMessage("holds"));
        Asserter::testFail(false, TestMessage("does not hold"));
    });
    EXPECT_EQ(o.events, (Lines{"start-test t", "failure t: does not hold", "end-test t"}));
    EXPECT_EQ(o.status, TestStatus::Failed);
}

TEST(Assert, AssertFailStopsTheTestAsFailed) {
    bool after = false;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("stop");
        after = true;
    });
    EXPECT_FALSE(after);
    EXPECT_EQ(o.status, TestStatus::Failed);
}

TEST(Assert, AssertFailIfTrueStopsOnlyWhenTrue) {
    int reached = 0;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_TRUE(false, "go on");
        reached = 1;
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_TRUE(true, "stop");
        reached = 2;
    });
    EXPECT_EQ(reached, 1);
    EXPECT_EQ(o.status, TestStatus::Failed);
    EXPECT_EQ(o.record.at(0).message.getMessage(), "stop");
}

TEST(Assert, AssertFailIfFalseStopsOnlyWhenFalse) {
    int reached = 0;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(true, "go on");
        reached = 1;
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(false, "stop");
        reached = 2;
    });
    EXPECT_EQ(reached, 1);
    EXPECT_EQ(o.status, TestStatus::Failed);
}

TEST(Assert, AssertErrorStopsTheTestWithAnError) {
    bool after = false;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR("broken");
        after = true;
    });
    EXPECT_FALSE(after);
    EXPECT_EQ(o.status, TestStatus::Error);
}

TEST(Assert, AssertErrorIfTrueStopsOnlyWhenTrue) {
    int reached = 0;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_TRUE(false, "go on");
        reached = 1;
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_TRUE(true, "stop");
        reached = 2;
    });
    EXPECT_EQ(reached, 1);
    EXPECT_EQ(o.status, TestStatus::Error);
}

TEST(Assert, AssertErrorIfFalseStopsOnlyWhenFalse) {
    int reached = 0;
    Outcome o = runBody([&] {
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(true, "go on");
        reached = 1;
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(false, "stop");
        reached = 2;
    });
    EXPECT_EQ(reached, 1);
    EXPECT_EQ(o.status, TestStatus::Error);
}

TEST(Assert, AssertCriticalStopsWithAnErrorAndMarksCritical) {
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    LambdaTest test("t", [] { ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL("robot fell"); });
    test.run(result);
    EXPECT_EQ(collector.suites().at(0).tests.at(0).status, TestStatus::Error);
    EXPECT_TRUE(test.hasCriticalError());
}

TEST(Assert, MessagesCarryTheSourceFileAndLine) {
    unsigned int line = 0;
    Outcome o = runBody([&] {
        line = __LINE__ + 1;
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(true, "here");
    });
    EXPECT_EQ(o.record.at(0).message.getSourceLineNumber(), line);
    EXPECT_NE(o.record.at(0).message.getSourceFileName().find("assert_test.cpp"),
              std::string::npos);
}

TEST(Assert, MessagesAcceptFormattedStrings) {
    Outcome o = runBody([] {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT(Asserter::format("joint %d at %.1f deg", 3, 12.5));
    });
    EXPECT_TRUE(contains(o.events, "report t: joint 3 at 12.5 deg"));
}

TEST(Assert, FormatHandlesLongOutput) {
    const std::string big(1000, 'x');
    EXPECT_EQ(Asserter::format("<%s>", big.c_str()), "<" + big + ">");
}

// Each macro is a single statement: it must compile as the body of an unbraced if/else.
TEST(Assert, EveryMacroWorksInAnUnbracedIfElse) {
    int branch = 0;
    Outcome o = runBody([&] {
        const bool x = branch == 0;
        if (x)
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("then");
        else
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("else");
        if (x)
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "then");
        else
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "else");
        if (x)
            ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(false, "then");
        else
            ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(false, "else");
        if (x)
            ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(true, "then");
        else
            ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(true, "else");
        if (!x)
            ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("then");
        else
            ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_TRUE(false, "else");
        if (x)
            ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(true, "then");
        else
            ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(true, "else");
        if (!x)
            ROBOTTESTINGFRAMEWORK_ASSERT_ERROR("then");
        else
            ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_TRUE(false, "else");
        if (x)
            ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(true, "then");
        else
            ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(true, "else");
        if (!x)
            ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL("then");
        else
            branch = 1;
    });
    EXPECT_EQ(branch, 1);
    EXPECT_EQ(o.status, TestStatus::Passed);
    EXPECT_TRUE(contains(o.events, "report t: then"));
    EXPECT_TRUE(contains(o.events, "check t: then"));
}

TEST(Assert, FixtureReportGoesToTheSuiteThroughTheFixture) {
    struct ReportingFixture : FixtureManager {
        bool setup(int, char**) override {
            ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("world ready");
            return true;
        }
    } fixture;
    fixture.setName("world");
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    TestSuite suite("s");
    suite.addFixtureManager(&fixture);
    suite.run(result);
    EXPECT_TRUE(contains(eventLines(collector), "report s: world ready"));
    ASSERT_EQ(collector.suites().at(0).events.size(), 1u);
}

TEST(Assert, WithNoRunningTestMessagesGoToStderr) {
    testing::internal::CaptureStderr();
    ROBOTTESTINGFRAMEWORK_TEST_REPORT("nobody listens");
    ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(true, "lost failure");
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("nobody listens"), std::string::npos);
    EXPECT_NE(err.find("lost failure"), std::string::npos);
}

TEST(Assert, AssertOutsideATestStillThrows) {
    EXPECT_THROW(ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("x"), TestFailureException);
    EXPECT_THROW(ROBOTTESTINGFRAMEWORK_ASSERT_ERROR("x"), TestErrorException);
    EXPECT_THROW(ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL("x"), TestCriticalErrorException);
}
