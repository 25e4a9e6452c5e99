// Prints the run as it happens: a line per test with its state and duration, and with
// verbose on, its reports and what it printed.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResultCollector.h>

namespace robottestingframework {

class ConsoleListener : public TestListener {
public:
    explicit ConsoleListener(bool verbose = false);

    // Reports are hidden; failures and errors are still shown.
    void hideUncriticalMessages() { hideUncritical_ = true; }
    // Beyond RTF 2.x: show every check (the runner's --detail).
    void showChecks(bool show) {
        showChecks_ = show;
        own_.setKeepChecks(show);  // checks are printed at the end of a test only then
    }
    // Beyond RTF 2.x: reads the run's records from `collector` instead of keeping records of
    // its own (nullptr, the default: its own). `collector` must hear every event before this
    // listener (added first to the same TestResult), keep checks when they are shown
    // (showChecks), and outlive the run: the runner's console reads the run's collector.
    void readRecordsOf(const TestResultCollector* collector) { shared_ = collector; }
    // Beyond RTF 2.x: where to print (stdout by default), and whether to use colours.
    void setStream(std::FILE* stream);
    void setColors(bool colors) { colors_ = colors; }
    // Beyond RTF 2.x: false leaves the summary out at the end (the runner's --no-summary); the
    // closing line "N passed, N failed" is always printed.
    void showSummary(bool show) { showSummary_ = show; }
    // Beyond RTF 2.x: a failing test runs again up to `retries` times (the runner's
    // --retries). An attempt that will run again is shown as RETRY, not FAILED: only the
    // last attempt's line says how the test ended.
    void setRetries(unsigned int retries) { retries_ = retries; }

    void startTest(const Test* test) override;
    void endTest(const Test* test) override;
    void startTestSuite(const TestSuite* suite) override;
    void endTestSuite(const TestSuite* suite) override;
    void startTestRunner() override;
    void endTestRunner() override;
    void retryTest(const Test* test, TestMessage msg) override;
    void addOutput(const Test* test, const std::string& text) override;
    void renameTest(const Test* test, const std::string& name) override;
    // Reads the record: a message or a problem (the table's columns) is said (and recorded, in
    // its own records); the frames, output and retries go to the handlers above. Its own
    // records time each event when it happened (as the run's collector does): a test's time on
    // the console is the reports' time.
    void onEvent(const RunEvent& event) override;

private:
    // A message (its word and colour from the table), printed when it is due.
    void say(const Test* test, const ResultEvent& event);
    void message(const char* label, const char* colour, const TestMessage& msg);
    // Prints `msg` now when it belongs to no open test or verbose is on; otherwise it is
    // printed under the test's line at endTest.
    bool printNow(const Test* test) const;
    // Writes `text` and its newline in one call (flushed on a terminal).
    void line(std::string text);
    // The records it reads: the run's collector (readRecordsOf), else its own.
    const TestResultCollector& records() const { return shared_ != nullptr ? *shared_ : own_; }

    std::FILE* stream_;
    bool tty_ = false;
    std::uint64_t test_ = 0;  // the open test's id (0: none)
    bool verbose_;
    bool hideUncritical_ = false;
    bool showChecks_ = false;
    bool showSummary_ = true;
    bool colors_ = false;
    unsigned int retries_ = 0;
    // Without the run's collector: enough of the current test to print its line at the end, and
    // counts for the summary.
    TestResultCollector own_;
    const TestResultCollector* shared_ = nullptr;
    // For each open suite, how many suites had failed when it started (its inner suites'
    // failures added): it failed when the count grew by its end.
    std::vector<std::size_t> failedSuitesAt_;
};

}  // namespace robottestingframework
