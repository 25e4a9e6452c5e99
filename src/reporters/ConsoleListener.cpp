#include <robottestingframework/ConsoleListener.h>

#include <unistd.h>

#include <utility>

#include <robottestingframework/Test.h>
#include <robottestingframework/TestSuite.h>

#include "core/text_safety.h"
#include "reporters/summary.h"

namespace robottestingframework {

namespace {

using namespace reporters::colour;
using reporters::colourOf;

// An event's colour: its kind's tone (the table).
const char* colourOf(const ResultEvent& event) {
    switch (toneOf(event.kind)) {
        case KindTone::Plain:
            return nullptr;
        case KindTone::Outcome:
            return event.passed ? green : red;
        case KindTone::Warn:
            return yellow;
        case KindTone::Bad:
            break;
    }
    return red;
}

}  // namespace

ConsoleListener::ConsoleListener(bool verbose) : verbose_(verbose) {
    // It only needs the open test and the counts; finished records are dropped.
    own_.setKeepEvents(false);
    own_.setCountTestsNotRun(true);  // its closing line counts the skipped lines it printed
    own_.setKeepChecks(showChecks_);
    setStream(stdout);
}

void ConsoleListener::setStream(std::FILE* stream) {
    stream_ = stream ? stream : stdout;
    tty_ = ::isatty(::fileno(stream_)) == 1;
}

void ConsoleListener::onEvent(const RunEvent& event) {
    ResultEvent scratch;
    const ResultEvent& data = shownEvent(event.data, scratch);
    if (isSaid(data)) {
        if (shared_ == nullptr) {
            own_.onEvent(event);
        }
        say(event.test, data);
        return;
    }
    if (isMessage(data.kind)) {
        // A check is said with --detail; a report with -v, unless uncritical messages are
        // hidden. A failed check is said once, by its failure that follows.
        if (isCheck(data.kind) ? showChecks_ && !isFailedCheck(data)
                               : verbose_ && !hideUncritical_) {
            say(event.test, data);
        }
        if (shared_ == nullptr) {
            own_.onEvent(event);
        }
        return;
    }
    if (shared_ != nullptr) {
        TestListener::onEvent(event);  // the run's collector has it already
        return;
    }
    const RunEvent* before = own_.timeAs(&event);
    try {
        TestListener::onEvent(event);
    } catch (...) {
        own_.timeAs(before);
        throw;
    }
    own_.timeAs(before);
}

void ConsoleListener::line(std::string text) {
    text += '\n';
    std::fwrite(text.data(), 1, text.size(), stream_);
    // A terminal shows progress as it happens; a file or a pipe gets buffered writes.
    if (tty_) {
        std::fflush(stream_);
    }
}

void ConsoleListener::message(const char* label, const char* colour, const TestMessage& msg) {
    std::string text = "      ";
    if (colors_ && colour != nullptr) {
        text += colour;
        text += label;
        text += plain;
    } else {
        text += label;
    }
    text += ": " + reporters::shownMessage(msg, "          ");
    line(std::move(text));
}

bool ConsoleListener::printNow(const Test* test) const {
    return verbose_ || test_ == 0 || test == nullptr || test->getId() != test_;
}

void ConsoleListener::say(const Test* test, const ResultEvent& event) {
    if (printNow(test)) {
        message(labelOf(event.kind, event.passed), colourOf(event), event.message);
    }
}

void ConsoleListener::retryTest(const Test* test, TestMessage msg) {
    if (shared_ == nullptr) {
        own_.retryTest(test, msg);
    }
    message("retry", yellow, msg);
}

void ConsoleListener::addOutput(const Test* test, const std::string& text) {
    if (shared_ == nullptr) {
        own_.addOutput(test, text);
    }
    if (!verbose_ || text.empty()) {
        return;
    }
    for (const std::string& shown : reporters::outputLines(text)) {
        line(shown);
    }
}

void ConsoleListener::renameTest(const Test* test, const std::string& name) {
    if (shared_ == nullptr) {
        own_.renameTest(test, name);
    }
}

void ConsoleListener::startTest(const Test* test) {
    if (shared_ == nullptr) {
        own_.startTest(test);
    }
    test_ = test != nullptr ? test->getId() : 0;
    if (verbose_ && test != nullptr) {
        const TestResultCollector& records = this->records();
        const std::string suite = records.suites().empty() ? "" : records.suites().back().name;
        line("  run         " + reporters::shownId(suite, test->getKey(), test->getName()));
    }
}

void ConsoleListener::endTest(const Test* test) {
    if (shared_ == nullptr) {
        own_.endTest(test);
    }
    test_ = 0;
    const TestResultCollector& records = this->records();
    if (records.suites().empty()) {
        return;
    }
    // The test's own record, found by id: the last of that id, which the test that just ended
    // is (the run's collector keeps every record of the suite; its own, the running tests').
    const std::uint64_t id = test != nullptr ? test->getId() : 0;
    const std::vector<TestRecord>& tests = records.suites().back().tests;
    const TestRecord* found = nullptr;
    for (auto candidate = tests.rbegin(); candidate != tests.rend(); ++candidate) {
        if (candidate->id == id) {
            found = &*candidate;
            break;
        }
    }
    if (found == nullptr) {
        return;
    }
    const TestRecord& record = *found;
    // The runner runs a failed attempt again while it has retries left (an interrupted one
    // never): that attempt did not decide the test's state.
    const bool retried = isFailure(record.status) && record.status != TestStatus::Interrupted &&
                         record.attempts.size() < retries_;
    // The word padded to 11 columns by hand: snprintf's "%-11s" cost more than the rest of
    // the line, once per test.
    std::string word = retried ? "RETRY" : reporters::statusWord(record.status);
    if (word.size() < 11) {
        word.append(11 - word.size(), ' ');
    }
    std::string text;
    text.reserve(word.size() + record.key.size() + record.name.size() + 48);
    text += "  ";
    if (colors_) {
        text += retried ? yellow : colourOf(record.status);
        text += word;
        text += plain;
    } else {
        text += word;
    }
    text += ' ';
    reporters::appendShownId(text, records.suites().back().name, record.key, record.name);
    text.append("  (").append(reporters::seconds(record.duration)).append(")");
    line(std::move(text));
    if (verbose_) {
        return;  // its messages were printed as they came
    }
    std::vector<ResultEvent> scratch;  // its measurements among its events
    for (const ResultEvent& event : record.eventsInOrder(scratch)) {
        if (isMessage(event.kind) && (!isCheck(event.kind) || !showChecks_)) {
            continue;
        }
        if (isFailedCheck(event)) {
            continue;  // said once, by its failure that follows
        }
        message(labelOf(event.kind, event.passed), colourOf(event), event.message);
    }
}

void ConsoleListener::startTestSuite(const TestSuite* suite) {
    if (shared_ == nullptr) {
        own_.startTestSuite(suite);
    }
    failedSuitesAt_.push_back(records().failedSuiteCount());
    if (suite == nullptr) {
        return;
    }
    const std::size_t count = suite->size();
    std::string text = "\n";
    text += colors_ ? bold : "";
    text += "suite " + reporters::visibleText(suite->getName());
    text += colors_ ? plain : "";
    text += "  (" + std::to_string(count) + (count == 1 ? " test)" : " tests)");
    line(std::move(text));
    if (verbose_ && !suite->getDescription().empty()) {
        line("  " + reporters::visibleText(suite->getDescription()));
    }
}

void ConsoleListener::endTestSuite(const TestSuite* suite) {
    if (shared_ == nullptr) {
        own_.endTestSuite(suite);
    }
    // Its own records were dropped test by test; the collector's count still knows.
    const TestResultCollector& records = this->records();
    const std::size_t failed = records.failedSuiteCount();
    std::size_t failedBefore = failed;  // a suite that never started: nothing counted
    if (!failedSuitesAt_.empty()) {
        failedBefore = failedSuitesAt_.back();
        failedSuitesAt_.pop_back();
    }
    if (!failedSuitesAt_.empty()) {
        failedSuitesAt_.back() += failed - failedBefore;  // not the outer suite's failure
    }
    if (suite == nullptr || records.suites().empty()) {
        return;
    }
    const SuiteRecord& record = records.suites().back();
    const bool ok = failed == failedBefore;
    std::string text = "  suite ";
    if (colors_) {
        text += ok ? green : red;
    }
    text += ok ? "passed" : "FAILED";
    text += colors_ ? plain : "";
    text += "  " + reporters::visibleText(record.name) + "  (" +
            reporters::seconds(record.duration) + ")";
    line(std::move(text));
}

void ConsoleListener::startTestRunner() {
    if (shared_ == nullptr) {
        own_.startTestRunner();
    }
}

void ConsoleListener::endTestRunner() {
    if (shared_ == nullptr) {
        own_.endTestRunner();
    }
    const TestResultCollector& records = this->records();
    line("");
    if (showSummary_) {
        line("Summary");
        for (const std::string& text : reporters::summaryLines(records)) {
            line(text);
        }
    }
    const std::string closing = reporters::closingLine(records);
    if (colors_) {
        line(std::string(records.failedCount() > 0 ? red : green) + closing + plain);
    } else {
        line(closing);
    }
    std::fflush(stream_);
}

}  // namespace robottestingframework
