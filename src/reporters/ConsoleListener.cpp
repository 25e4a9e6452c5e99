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
using Kind = ResultEvent::Kind;

const char* colourOf(Kind kind, bool passed) {
    switch (kind) {
        case Kind::Check:
            return passed ? green : red;
        case Kind::Skipped:
            return yellow;
        case Kind::Report:
            return nullptr;
        default:
            return red;
    }
}

}  // namespace

ConsoleListener::ConsoleListener(bool verbose) : verbose_(verbose) {
    // It only needs the open test and the counts; finished records are dropped.
    record_.setKeepEvents(false);
    record_.setCountTestsNotRun(true);  // its closing line counts the skipped lines it printed
    record_.setKeepChecks(showChecks_);
    setStream(stdout);
}

void ConsoleListener::setStream(std::FILE* stream) {
    stream_ = stream ? stream : stdout;
    tty_ = ::isatty(::fileno(stream_)) == 1;
}

void ConsoleListener::onEvent(const RunEvent& event) {
    const RunEvent* before = record_.timeAs(&event);
    try {
        TestListener::onEvent(event);
    } catch (...) {
        record_.timeAs(before);
        throw;
    }
    record_.timeAs(before);
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

void ConsoleListener::addReport(const Test* test, TestMessage msg) {
    record_.addReport(test, msg);
    if (verbose_ && !hideUncritical_) {
        message(toString(Kind::Report), colourOf(Kind::Report, true), msg);
    }
}

void ConsoleListener::addError(const Test* test, TestMessage msg) {
    record_.addError(test, msg);
    say(Kind::Error, test, msg);
}

void ConsoleListener::addFailure(const Test* test, TestMessage msg) {
    record_.addFailure(test, msg);
    say(Kind::Failure, test, msg);
}

void ConsoleListener::addCheck(const Test* test, TestMessage msg, bool passed) {
    // Printed first, so that the record can take the message (a check per test: no copy).
    if (showChecks_) {
        say(Kind::Check, test, msg, passed);
    }
    record_.addCheck(test, std::move(msg), passed);
}

void ConsoleListener::addEvent(const Test* test, const ResultEvent& event) {
    if (event.kind == Kind::World) {
        return;  // about no test; the runner says it itself
    }
    record_.addEvent(test, event);
    say(event.kind, test, event.message, event.passed);
}

void ConsoleListener::say(ResultEvent::Kind kind, const Test* test, const TestMessage& msg,
                          bool passed) {
    if (printNow(test)) {
        message(reporters::eventLabel(kind, passed).c_str(), colourOf(kind, passed), msg);
    }
}

void ConsoleListener::addSkipped(const Test* test, TestMessage reason) {
    record_.addSkipped(test, reason);
    say(Kind::Skipped, test, reason);
}

void ConsoleListener::retryTest(const Test* test, TestMessage msg) {
    record_.retryTest(test, msg);
    message(toString(Kind::Retry), yellow, msg);
}

void ConsoleListener::addCrash(const Test* test, TestMessage msg) {
    record_.addCrash(test, msg);
    say(Kind::Crash, test, msg);
}

void ConsoleListener::addTimeout(const Test* test, TestMessage msg) {
    record_.addTimeout(test, msg);
    say(Kind::Timeout, test, msg);
}

void ConsoleListener::addInterrupted(const Test* test, TestMessage msg) {
    record_.addInterrupted(test, msg);
    say(Kind::Interrupted, test, msg);
}

void ConsoleListener::addOutput(const Test* test, const std::string& text) {
    record_.addOutput(test, text);
    if (!verbose_ || text.empty()) {
        return;
    }
    for (const std::string& shown : reporters::outputLines(text)) {
        line(shown);
    }
}

void ConsoleListener::renameTest(const Test* test, const std::string& name) {
    record_.renameTest(test, name);
}

void ConsoleListener::startTest(const Test* test) {
    record_.startTest(test);
    test_ = test != nullptr ? test->getId() : 0;
    if (verbose_ && test != nullptr) {
        line("  run         " + reporters::shownAs(test->getKey(), test->getName()));
    }
}

void ConsoleListener::endTest(const Test* test) {
    record_.endTest(test);
    test_ = 0;
    if (record_.suites().empty()) {
        return;
    }
    // The test's own record, found by id (only the running tests' records are kept).
    const std::uint64_t id = test != nullptr ? test->getId() : 0;
    const TestRecord* found = nullptr;
    for (const TestRecord& candidate : record_.suites().back().tests) {
        if (candidate.id == id) {
            found = &candidate;
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
    reporters::appendShownAs(text, record.key, record.name);
    text.append("  (").append(reporters::seconds(record.duration)).append(")");
    line(std::move(text));
    if (verbose_) {
        return;  // its messages were printed as they came
    }
    std::vector<ResultEvent> scratch;  // its measurements among its events
    for (const ResultEvent& event : record.eventsInOrder(scratch)) {
        if (event.kind == Kind::Report || (event.kind == Kind::Check && !showChecks_)) {
            continue;
        }
        message(reporters::eventLabel(event.kind, event.passed).c_str(),
                colourOf(event.kind, event.passed), event.message);
    }
}

void ConsoleListener::startTestSuite(const TestSuite* suite) {
    record_.startTestSuite(suite);
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
    // Its records were dropped test by test; the collector's count still knows.
    const std::size_t failedBefore = record_.failedSuiteCount();
    record_.endTestSuite(suite);
    if (suite == nullptr || record_.suites().empty()) {
        return;
    }
    const SuiteRecord& record = record_.suites().back();
    const bool ok = record_.failedSuiteCount() == failedBefore;
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
    record_.startTestRunner();
}

void ConsoleListener::endTestRunner() {
    record_.endTestRunner();
    line("");
    if (showSummary_) {
        line("Summary");
        for (const std::string& text : reporters::summaryLines(record_)) {
            line(text);
        }
    }
    const std::string closing = reporters::closingLine(record_);
    if (colors_) {
        line(std::string(record_.failedCount() > 0 ? red : green) + closing + plain);
    } else {
        line(closing);
    }
    std::fflush(stream_);
}

}  // namespace robottestingframework
