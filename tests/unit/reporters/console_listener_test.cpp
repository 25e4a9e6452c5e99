#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>

#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>

#include "core_test_helpers.h"

using namespace rtf_test;

namespace {

// Runs `suites` through a console listener writing to a file; returns the text. `collector`:
// the run's collector the console reads (as the runner's does), added before it; nullptr: the
// console keeps records of its own (as RTF 2.x's users make it).
std::string consoleTextOf(
    const std::vector<TestSuite*>& suites,
    std::function<void(ConsoleListener&)> configure = [](ConsoleListener&) {}, bool verbose = false,
    TestResultCollector* collector = nullptr) {
    const std::string path = (scratchDir() / "console.txt").string();
    std::FILE* file = std::fopen(path.c_str(), "w");
    EXPECT_NE(file, nullptr);
    ConsoleListener console(verbose);
    console.setStream(file);
    configure(console);
    TestRunner runner;
    for (TestSuite* suite : suites) {
        runner.addTest(suite);
    }
    TestResult result;
    if (collector != nullptr) {
        result.addListener(collector);
        console.readRecordsOf(collector);
    }
    result.addListener(&console);
    runner.run(result);
    std::fclose(file);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs `tests` in a suite "arm tests" (consoleTextOf).
std::string consoleText(
    std::vector<Test*> tests,
    std::function<void(ConsoleListener&)> configure = [](ConsoleListener&) {}, bool verbose = false,
    TestResultCollector* collector = nullptr) {
    TestSuite suite("arm tests");
    for (Test* test : tests) {
        suite.addTest(test);
    }
    return consoleTextOf({&suite}, std::move(configure), verbose, collector);
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

// The runner's console reads the run's collector instead of keeping records of its own (issue
// 37): what it prints is the same, but for the times.
TEST(ConsoleListener, ReadingTheRunsCollectorPrintsWhatItsOwnRecordsDo) {
    auto run = [](bool verbose, bool checks, TestResultCollector* collector) {
        LambdaTest passing("encoders", [] { ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "read"); });
        LambdaTest failing("camera", [] {
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("warming up");
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(false, "no image");
        });
        LambdaTest thrower("gripper", [] { throw 42; });
        std::string text = consoleText(
            {&passing, &failing, &thrower}, [checks](ConsoleListener& c) { c.showChecks(checks); },
            verbose, collector);
        // The times differ from run to run: each "(0.000 s)" and the summary's time go.
        std::string timeless;
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);) {
            const std::size_t time = line.rfind("  (");
            if (line.rfind("  time:", 0) == 0) {
                continue;
            }
            timeless +=
                (time != std::string::npos && line.back() == ')' ? line.substr(0, time) : line) +
                "\n";
        }
        return timeless;
    };
    for (bool verbose : {false, true}) {
        for (bool checks : {false, true}) {
            TestResultCollector collector;
            collector.setCountTestsNotRun(true);
            collector.setKeepChecks(checks);
            const std::string own = run(verbose, checks, nullptr);
            const std::string read = run(verbose, checks, &collector);
            EXPECT_EQ(read, own) << "verbose " << verbose << ", checks " << checks;
            EXPECT_TRUE(has(read, "  FAILED      camera")) << read;
            EXPECT_TRUE(has(read, "  suite FAILED  arm tests")) << read;
            EXPECT_EQ(lastLine(read), "1 passed, 2 failed") << read;
            EXPECT_EQ(collector.testCount(), 3u);  // it read them, and kept none of its own
        }
    }
}

// A suite passes or fails by its own tests, whichever records the console reads: the first
// suite's failure does not make the second one's line say FAILED.
TEST(ConsoleListener, ReadingTheRunsCollectorEachSuiteSaysItsOwnState) {
    LambdaTest failing("a", [] { ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("no"); }), passing("b");
    TestSuite first("first"), second("second");
    first.addTest(&failing);
    second.addTest(&passing);
    TestResultCollector collector;
    const std::string text = consoleTextOf(
        {&first, &second}, [](ConsoleListener&) {}, false, &collector);
    EXPECT_TRUE(has(text, "  suite FAILED  first")) << text;
    EXPECT_TRUE(has(text, "  suite passed  second")) << text;
    EXPECT_EQ(lastLine(text), "1 passed, 1 failed") << text;
}

// Issue 38, friction 9: the whole multi-line reason of a fixture that failed was printed again
// under each skipped test of the suite. The suite's error says it once; each skipped test says
// one line referring to it.
TEST(ConsoleListener, AFixtureFailureIsSaidOnceAndEachSkippedTestInALine) {
    class World : public FixtureManager {
    public:
        bool setup(int /*argc*/, char** /*argv*/) override {
            throw std::runtime_error("the world did not start\n  | first-said\n  | last-said");
        }
        void tearDown() override {}
    } world;
    LambdaTest a("a"), b("b"), c("c");
    TestSuite suite("robot");
    suite.addFixtureManager(&world);
    suite.addTest(&a);
    suite.addTest(&b);
    suite.addTest(&c);
    for (bool shared : {false, true}) {
        TestResultCollector collector;
        const std::string text = consoleTextOf(
            {&suite}, [](ConsoleListener&) {}, false, shared ? &collector : nullptr);
        std::size_t said = 0;
        for (std::size_t at = text.find("| last-said"); at != std::string::npos;
             at = text.find("| last-said", at + 1)) {
            ++said;
        }
        EXPECT_EQ(said, 1u) << text;
        std::size_t skipped = 0;
        // The first line of the reason only (`| last-said` is said once, above).
        const std::string line =
            "      skipped: the suite's fixture failed (see the suite's error): fixture ";
        for (std::size_t at = text.find(line); at != std::string::npos;
             at = text.find(line, at + 1)) {
            ++skipped;
        }
        EXPECT_EQ(skipped, 3u) << text;
    }
}
