#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>

#include "core_test_helpers.h"

using namespace rtf_test;

namespace {

// Runs `tests` in a suite through a console listener writing to a file; returns the text.
std::string consoleText(
    std::vector<Test*> tests,
    std::function<void(ConsoleListener&)> configure = [](ConsoleListener&) {},
    bool verbose = false) {
    const std::string path = (scratchDir() / "console.txt").string();
    std::FILE* file = std::fopen(path.c_str(), "w");
    EXPECT_NE(file, nullptr);
    ConsoleListener console(verbose);
    console.setStream(file);
    configure(console);
    TestSuite suite("arm tests");
    for (Test* test : tests) {
        suite.addTest(test);
    }
    TestRunner runner;
    runner.addTest(&suite);
    TestResult result;
    result.addListener(&console);
    runner.run(result);
    std::fclose(file);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string lastLine(const std::string& text) {
    const std::size_t end = text.find_last_not_of('\n');
    const std::size_t begin = text.rfind('\n', end);
    return text.substr(begin == std::string::npos ? 0 : begin + 1, end - begin);
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(ConsoleListener, ClosingLineCountsPassedAndFailed) {
    LambdaTest a("a"), b("b", [] { ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("no"); });
    LambdaTest c("c", [] { throw 42; });
    EXPECT_EQ(lastLine(consoleText({&a, &b, &c})), "1 passed, 2 failed");
}

TEST(ConsoleListener, ClosingLineAddsSkippedWhenThereAreAny) {
    LambdaTest a("a", [] { ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL("stop"); }), b("b");
    EXPECT_EQ(lastLine(consoleText({&a, &b})), "0 passed, 1 failed, 1 skipped");
}

TEST(ConsoleListener, PrintsALinePerTestWithStatusAndDuration) {
    LambdaTest a("encoders"), b("camera", [] { ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("no image"); });
    const std::string text = consoleText({&a, &b});
    EXPECT_TRUE(has(text, "suite arm tests  (2 tests)"));
    EXPECT_TRUE(has(text, "  passed      encoders  (0."));
    EXPECT_TRUE(has(text, "  FAILED      camera  (0."));
    EXPECT_TRUE(has(text, " s)\n"));
}

// Issue 38: the line names the test by the id --filter takes ("SUITE/KEY"), the same as the -j N
// console's, with the name the test gave itself beside it when that differs.
TEST(ConsoleListener, ATestWithAnIdIsNamedByItAsFilterTakesIt) {
    LambdaTest a("t.py"), b("Gripper");
    a.setKey("t.py[--speed 80]");
    b.setKey("tests/gripper.py");
    const std::string text = consoleText(
        {&a, &b}, [](ConsoleListener&) {}, true);
    EXPECT_TRUE(has(text, "  passed      arm tests/t.py[--speed 80] (t.py)  (0.")) << text;
    EXPECT_TRUE(has(text, "  passed      arm tests/tests/gripper.py (Gripper)  (0.")) << text;
    EXPECT_TRUE(has(text, "  run         arm tests/tests/gripper.py (Gripper)\n")) << text;
}

TEST(ConsoleListener, FailuresAreShownWithTheirSourceLocation) {
    LambdaTest b("camera", [] { ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("no image"); });
    const std::string text = consoleText({&b});
    EXPECT_TRUE(has(text, "failure: no image [")) << text;
    EXPECT_TRUE(has(text, "console_listener_test.cpp:")) << text;
}

TEST(ConsoleListener, ReportsAndOutputOnlyWhenVerbose) {
    auto body = [] { ROBOTTESTINGFRAMEWORK_TEST_REPORT("just saying"); };
    LambdaTest a("a", body);
    EXPECT_FALSE(has(consoleText({&a}), "just saying"));
    LambdaTest b("b", body);
    EXPECT_TRUE(has(consoleText(
                        {&b}, [](ConsoleListener&) {}, true),
                    "report: just saying"));
}

TEST(ConsoleListener, VerboseShowsTheTestsOutput) {
    LambdaTest* self = nullptr;
    LambdaTest a("a", [&] { self->getResult()->addOutput(self, "printed line\n"); });
    self = &a;
    EXPECT_TRUE(has(consoleText(
                        {&a}, [](ConsoleListener&) {}, true),
                    "| printed line"));
}

TEST(ConsoleListener, HideUncriticalMessagesHidesReportsButNotFailures) {
    LambdaTest a("a", [] {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("just saying");
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(true, "real problem");
    });
    const std::string text = consoleText(
        {&a}, [](ConsoleListener& c) { c.hideUncriticalMessages(); }, true);
    EXPECT_FALSE(has(text, "just saying"));
    EXPECT_TRUE(has(text, "real problem"));
}

TEST(ConsoleListener, SkipReasonIsShown) {
    LambdaTest a("a", [] { ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL("robot fell"); }), b("b");
    EXPECT_TRUE(has(consoleText({&a, &b}), "skipped: critical error in a: robot fell"));
}

TEST(ConsoleListener, ShowChecksPrintsEveryCheck) {
    LambdaTest a("a", [] {
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "fine");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(false, "broken");
    });
    const std::string text = consoleText({&a}, [](ConsoleListener& c) { c.showChecks(true); });
    EXPECT_TRUE(has(text, "check ok: fine"));
    // One line per failed check (issue 38, friction 9): its failure's.
    EXPECT_FALSE(has(text, "check FAILED: broken"));
    EXPECT_TRUE(has(text, "failure: broken"));
    EXPECT_EQ(text.find("broken"), text.rfind("broken"));
}

TEST(ConsoleListener, NoColoursUnlessAskedFor) {
    LambdaTest a("a");
    EXPECT_FALSE(has(consoleText({&a}), "\033["));
    LambdaTest b("b");
    EXPECT_TRUE(has(consoleText({&b}, [](ConsoleListener& c) { c.setColors(true); }), "\033[32m"));
}

TEST(ConsoleListener, SummaryCountsSuites) {
    LambdaTest a("a");
    const std::string text = consoleText({&a});
    EXPECT_TRUE(has(text, "suites: 1 (1 passed, 0 failed)"));
    EXPECT_TRUE(has(text, "tests:  1 (1 passed)"));
}

TEST(ConsoleListener, SuiteLineSaysFailedWhenAnEarlierTestFailed) {
    LambdaTest a("a", [] { ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("no"); }), b("b");
    EXPECT_TRUE(has(consoleText({&a, &b}), "  suite FAILED  arm tests"));
}

// Under a scheduler, a test's events reach the console after they happened (kept up to 100 ms):
// the console times them when they happened, as the reports do (issue 40, item 6).
TEST(ConsoleListener, ATestsTimeIsWhenItsEventsHappenedNotWhenTheyArrived) {
    const std::string path = (scratchDir() / "console-times.txt").string();
    std::FILE* file = std::fopen(path.c_str(), "w");
    ASSERT_NE(file, nullptr);
    ConsoleListener console;
    console.setStream(file);
    TestSuite suite("arm tests");
    LambdaTest test("grip");
    RunEvent start;
    start.data.kind = ResultEvent::Kind::StartSuite;
    start.test = &suite;
    start.suite = &suite;
    console.onEvent(start);
    RunEvent begin;
    begin.data.kind = ResultEvent::Kind::StartTest;
    begin.test = &test;
    begin.happened = 1000.0;
    RunEvent end = begin;
    end.data.kind = ResultEvent::Kind::EndTest;
    end.happened = 1000.5;  // half a second later, handed on at once
    console.onEvent(begin);
    console.onEvent(end);
    std::fclose(file);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_TRUE(has(text.str(), "grip  (0.500 s)")) << text.str();
}
