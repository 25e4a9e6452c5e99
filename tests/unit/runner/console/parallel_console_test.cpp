// The console of -j N (parallel_console.h): a line per test as it ends, its messages under it,
// the scheduler's notes, the progress line on a terminal, the summary at the end.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestSuite.h>

#include "core_test_helpers.h"
#include "runner/console/parallel_console.h"
#include "runner/schedule/suite_events.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

// A console writing to memory; text() is what it wrote, each test's time shown as "(T)".
class Console {
public:
    // `shared`: write to another console's stream (a progress line on the same one).
    explicit Console(ParallelConsoleSettings settings = {}, std::FILE* shared = nullptr) {
        stream_ = shared != nullptr ? shared : ::open_memstream(&buffer_, &size_);
        owned_ = shared == nullptr;
        console_ = std::make_unique<ParallelConsole>(stream_, collector_, settings);
    }
    ~Console() {
        console_.reset();
        if (owned_) {
            std::fclose(stream_);
            std::free(buffer_);
        }
    }
    std::FILE* stream() { return stream_; }
    ParallelConsole& operator*() { return *console_; }
    ParallelConsole* operator->() { return console_.get(); }
    TestResultCollector& collector() { return collector_; }

    // The events `report` publishes on a suite's queue, shown as the scheduler shows them.
    template <typename Report>
    void show(const TestSuite& suite, Report report) {
        SuiteEvents events([] {});
        TestResult result;
        result.addListener(&events);
        report(result);
        console_->events(suite, events.take());
    }

    std::string text() {
        std::fflush(stream_);
        return std::regex_replace(std::string(buffer_, size_), std::regex("  \\([^)]*s\\)\n"),
                                  "  (T)\n");
    }

private:
    TestResultCollector collector_;
    char* buffer_ = nullptr;
    std::size_t size_ = 0;
    bool owned_ = true;
    std::FILE* stream_ = nullptr;
    std::unique_ptr<ParallelConsole> console_;
};

}  // namespace

TEST(ParallelConsole, APassedTestIsOneLineNamingItsIdAsFilterTakesIt) {
    Console console;
    TestSuite suite("arm");
    rtf_test::LambdaTest reach("reach");
    reach.setKey("reach");
    console.show(suite, [&](TestResult& events) {
        events.startTest(&reach);
        events.endTest(&reach);
    });
    EXPECT_EQ(console.text(), "  passed      arm/reach  (T)\n");
}

TEST(ParallelConsole, AFailedTestShowsItsMessagesUnderItsLine) {
    Console console;
    TestSuite suite("arm");
    rtf_test::LambdaTest grip("grip");
    grip.setKey("grip");
    console.show(suite, [&](TestResult& events) {
        events.startTest(&grip);
        events.addFailure(&grip, TestMessage("dropped the cup"));
        // A failed check, as Asserter::testCheck gives it: the check, then its failure.
        events.addCheck(&grip, TestMessage("force within limits"), false);
        events.addFailure(&grip, TestMessage("force within limits"));
        events.addCheck(&grip, TestMessage("a passed check"), true);
        events.endTest(&grip);
    });
    // One line per failed check (issue 38, friction 9): its failure's, not "check FAILED".
    EXPECT_EQ(console.text(),
              "  FAILED      arm/grip  (T)\n"
              "      failure: dropped the cup\n"
              "      failure: force within limits\n");
}

TEST(ParallelConsole, TheWorstStateOfATestIsItsWord) {
    Console console;
    TestSuite suite("arm");
    rtf_test::LambdaTest grip("grip");
    grip.setKey("grip");
    console.show(suite, [&](TestResult& events) {
        events.startTest(&grip);
        events.addTimeout(&grip, TestMessage("after 2 s"));
        events.addFailure(&grip, TestMessage("late"));
        events.endTest(&grip);
    });
    EXPECT_EQ(console.text().substr(0, 22), "  TIMED OUT   arm/grip");
}

TEST(ParallelConsole, TestsOfSeveralSuitesInterleaveWholeLines) {
    Console console;
    TestSuite arm("arm");
    TestSuite leg("leg");
    rtf_test::LambdaTest reach("reach");
    reach.setKey("reach");
    rtf_test::LambdaTest walk("walk");
    walk.setKey("walk");
    console.show(arm, [&](TestResult& events) { events.startTest(&reach); });
    console.show(leg, [&](TestResult& events) {
        events.startTest(&walk);
        events.addError(&walk, TestMessage("no floor"));
        events.endTest(&walk);
    });
    console.show(arm, [&](TestResult& events) { events.endTest(&reach); });
    EXPECT_EQ(console.text(),
              "  ERROR       leg/walk  (T)\n"
              "      error: no floor\n"
              "  passed      arm/reach  (T)\n");
}

TEST(ParallelConsole, AFailureWithRetriesLeftIsARetryAndALaterPassIsFlaky) {
    ParallelConsoleSettings settings;
    settings.retries = 1;
    Console console(settings);
    TestSuite suite("arm");
    rtf_test::LambdaTest grip("grip");
    grip.setKey("grip");
    console.show(suite, [&](TestResult& events) {
        events.startTest(&grip);
        events.addFailure(&grip, TestMessage("slipped"));
        events.endTest(&grip);
        events.retryTest(&grip, TestMessage("attempt 2 of 2"));
        events.startTest(&grip);
        events.endTest(&grip);
    });
    EXPECT_EQ(console.text(),
              "  RETRY       arm/grip  (T)\n"
              "      failure: slipped\n"
              "  retry       arm/grip: attempt 2 of 2\n"
              "  FLAKY       arm/grip  (T)\n");
}

TEST(ParallelConsole, AFailureWithoutRetriesLeftIsFinal) {
    ParallelConsoleSettings settings;
    settings.retries = 1;
    Console console(settings);
    TestSuite suite("arm");
    rtf_test::LambdaTest grip("grip");
    grip.setKey("grip");
    console.show(suite, [&](TestResult& events) {
        events.startTest(&grip);
        events.addCrash(&grip, TestMessage("signal 11"));
        events.endTest(&grip);
        events.retryTest(&grip, TestMessage("attempt 2 of 2"));
        events.startTest(&grip);
        events.addCrash(&grip, TestMessage("signal 11"));
        events.endTest(&grip);
    });
    const std::string text = console.text();
    EXPECT_NE(text.find("  RETRY       arm/grip  (T)\n"), std::string::npos) << text;
    EXPECT_NE(text.find("  CRASHED     arm/grip  (T)\n      crash: signal 11\n"), std::string::npos)
        << text;
}

TEST(ParallelConsole, AnInterruptedTestIsNeverARetry) {
    ParallelConsoleSettings settings;
    settings.retries = 3;
    Console console(settings);
    TestSuite suite("arm");
    rtf_test::LambdaTest grip("grip");
    grip.setKey("grip");
    console.show(suite, [&](TestResult& events) {
        events.startTest(&grip);
        events.addInterrupted(&grip, TestMessage("Ctrl-C"));
        events.endTest(&grip);
    });
    EXPECT_EQ(console.text(), "  INTERRUPTED arm/grip  (T)\n      interrupted: Ctrl-C\n");
}

TEST(ParallelConsole, ReportsAndOutputAreShownOnlyWhenVerbose) {
    for (bool verbose : {false, true}) {
        ParallelConsoleSettings settings;
        settings.verbose = verbose;
        Console console(settings);
        TestSuite suite("arm");
        rtf_test::LambdaTest reach("reach");
        reach.setKey("reach");
        console.show(suite, [&](TestResult& events) {
            events.startTest(&reach);
            events.addReport(&reach, TestMessage("at 3 cm"));
            events.addOutput(&reach, "line one\nline two\n");
            events.endTest(&reach);
        });
        EXPECT_EQ(console.text(), verbose ? "  passed      arm/reach  (T)\n"
                                            "      report: at 3 cm\n"
                                            "      | line one\n"
                                            "      | line two\n"
                                          : "  passed      arm/reach  (T)\n");
    }
}

TEST(ParallelConsole, AProblemOutsideATestIsSaidAtOnceNamingTheSuite) {
    Console console;
    TestSuite suite("arm");
    console.show(suite, [&](TestResult& events) {
        events.addError(nullptr, TestMessage("fixture did not start"));
    });
    EXPECT_EQ(console.text(), "  arm: error: fixture did not start\n");
}

TEST(ParallelConsole, TheEndOfASuiteSaysWhetherItPassed) {
    Console console;
    TestSuite suite("arm");
    console.show(suite, [&](TestResult& events) { events.endTestSuite(&suite); });
    EXPECT_EQ(console.text(), "  suite passed  arm\n");
}

TEST(ParallelConsole, ColoursWrapTheStatusWord) {
    ParallelConsoleSettings settings;
    settings.colours = true;
    Console console(settings);
    TestSuite suite("arm");
    rtf_test::LambdaTest reach("reach");
    reach.setKey("reach");
    console.show(suite, [&](TestResult& events) {
        events.startTest(&reach);
        events.endTest(&reach);
    });
    const std::string text = console.text();
    EXPECT_EQ(text.rfind("  \033[", 0), 0u) << text;
    EXPECT_NE(text.find("passed     \033[0m arm/reach"), std::string::npos) << text;
}

TEST(ParallelConsole, ANoteIsALineNamingTheRunner) {
    Console console;
    console->note("suite leg waits for lock robot");
    EXPECT_EQ(console.text(), "robottestingframework-testrunner: suite leg waits for lock robot\n");
}

TEST(ParallelConsole, WithoutATerminalATestThatStartsShowsNothing) {
    Console console;
    TestSuite suite("arm");
    rtf_test::LambdaTest reach("reach");
    reach.setKey("reach");
    console.show(suite, [&](TestResult& events) { events.startTest(&reach); });
    console->note("x");
    EXPECT_EQ(console.text(), "robottestingframework-testrunner: x\n");
}

TEST(ParallelConsole, OnATerminalTheProgressLineIsErasedForEachLineAndDrawnAgain) {
    Console console;
    ProgressSettings progressSettings;
    progressSettings.tests = 3;
    progressSettings.redrawMilliseconds = 0;
    ProgressLine progress(console.stream(), progressSettings);
    ParallelConsoleSettings settings;
    settings.progress = &progress;
    Console withProgress(settings, console.stream());
    TestSuite suite("arm");
    rtf_test::LambdaTest reach("reach");
    reach.setKey("reach");
    withProgress.show(suite, [&](TestResult& events) { events.startTest(&reach); });
    withProgress->note("x");
    EXPECT_EQ(std::regex_replace(console.text(), std::regex("\\(\\d+\\.\\d s\\)"), "(T)"),
              "robottestingframework-testrunner: x\n[1/3] arm :: reach (T)");
}

TEST(ParallelConsole, TheEndOfTheRunErasesTheProgressLineAndEndsWithTheClosingLine) {
    Console console;
    ProgressSettings progressSettings;
    progressSettings.tests = 1;
    progressSettings.redrawMilliseconds = 0;
    ProgressLine progress(console.stream(), progressSettings);
    ParallelConsoleSettings settings;
    settings.progress = &progress;
    settings.summary = false;
    Console withProgress(settings, console.stream());
    TestSuite suite("arm");
    rtf_test::LambdaTest reach("reach");
    reach.setKey("reach");
    withProgress.show(suite, [&](TestResult& events) { events.startTest(&reach); });
    withProgress->note("x");
    withProgress->endTestRunner();
    const std::string text = console.text();
    EXPECT_EQ(text.find("Summary"), std::string::npos) << text;
    // Erased once more at the end, and never drawn again.
    const std::size_t last = text.rfind("[1/1]");
    ASSERT_NE(last, std::string::npos) << text;
    EXPECT_EQ(text.find("\r\033[K\n", last), text.find("\r\033[K", last)) << text;
}

TEST(ParallelConsole, TheSummaryComesFromTheCollector) {
    ParallelConsoleSettings settings;
    settings.summary = true;
    Console withSummary(settings);
    withSummary->endTestRunner();
    settings.summary = false;
    Console without(settings);
    without->endTestRunner();
    const std::string summary = withSummary.text();
    const std::string closing = without.text();
    EXPECT_EQ(summary.rfind("\nSummary\n", 0), 0u) << summary;
    // Both end with the same closing line.
    ASSERT_GT(closing.size(), 2u);
    EXPECT_EQ(summary.substr(summary.size() - (closing.size() - 1)), closing.substr(1));
}
