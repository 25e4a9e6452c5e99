#include "runner/console/parallel_console.h"

#include <chrono>

#include <robottestingframework/TestSuite.h>

#include "core/text_safety.h"
#include "reporters/summary.h"

namespace robottestingframework {
namespace runner {

namespace {

using namespace reporters::colour;

// When `event` happened (steady seconds): as the collector times it, so that a test's time on
// the console is the one the reports give (a kept event arrives up to SuiteEvents::kLookMs
// after it happened).
double happenedAt(const RunEvent& event) {
    if (event.happened > 0) {
        return event.happened;
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

}  // namespace

// Turns one suite's events into lines: a test's line when it ends.
class ParallelConsole::Live : public TestListener {
public:
    Live(ParallelConsole& console, const TestSuite& suite) : console_(console), suite_(suite) {}

    // Hands on `event`, timed when it happened.
    void deliver(const RunEvent& event) {
        happened_ = happenedAt(event);
        onEvent(event);
    }

    void startTest(const Test* test) override {
        if (ProgressLine* progress = console_.settings_.progress) {
            progress->testStarted(test, suiteName(), shownAs(test));
        }
        Open& open = open_()[test];
        const unsigned int attempts = open.attempts;  // a retry starts again
        open = Open();
        open.started = happened_;
        open.attempts = attempts;
    }
    void endTest(const Test* test) override {
        if (ProgressLine* progress = console_.settings_.progress) {
            progress->testEnded(test);
        }
        auto found = open_().find(test);
        if (found == open_().end()) {
            return;
        }
        const Open& open = found->second;
        const double took = happened_ - open.started;
        // As the -j1 console: an attempt that will run again did not decide the test's state
        // (an interrupted one never runs again), and a pass after a retry is flaky.
        const bool retried = isFailure(open.status) && open.status != TestStatus::Interrupted &&
                             open.attempts < console_.settings_.retries;
        const TestStatus shown = open.status == TestStatus::Passed && open.attempts > 0
                                     ? TestStatus::Flaky
                                     : open.status;
        char word[16];
        std::snprintf(word, sizeof(word), "%-11s",
                      retried ? "RETRY" : reporters::statusWord(shown));
        std::string text = "  ";
        if (console_.settings_.colours) {
            text += retried ? yellow : reporters::colourOf(shown);
            text += word;
            text += plain;
        } else {
            text += word;
        }
        text += " " + shownId(test) + "  (" + reporters::seconds(took) + ")";
        console_.line(text);
        for (const auto& said : open.lines) {
            console_.line(said);
        }
        if (retried) {
            // retryTest comes after endTest: keep the count of attempts for it.
            const unsigned int attempts = found->second.attempts;
            found->second = Open();
            found->second.attempts = attempts;
        } else {
            open_().erase(found);
        }
    }
    // Reads the record: a problem, a failed check and (with -v) a report are lines under
    // their test (the table's columns); the frames, output and retries go to the handlers.
    void onEvent(const RunEvent& event) override {
        ResultEvent scratch;
        const ResultEvent& data = shownEvent(event.data, scratch);
        if (isSaid(data)) {
            raise(event.test, data);
        } else if (isMessage(data.kind)) {
            // A failed check is said once, by its failure that follows.
            if (!isHiddenCheck(data) && !isFailedCheck(data) &&
                (isCheck(data.kind) || console_.settings_.verbose)) {
                raise(event.test, data);
            }
        } else {
            TestListener::onEvent(event);
        }
    }
    void addOutput(const Test* test, const std::string& text) override {
        auto found = open_().find(test);
        if (!console_.settings_.verbose || found == open_().end()) {
            return;
        }
        for (std::string& shown : reporters::outputLines(text)) {
            found->second.lines.push_back(std::move(shown));
        }
    }
    void renameTest(const Test* test, const std::string& name) override {
        auto found = open_().find(test);
        if (found != open_().end()) {
            found->second.name = name;
        }
        if (ProgressLine* progress = console_.settings_.progress) {
            progress->testRenamed(test, shownAs(test));
        }
    }
    void retryTest(const Test* test, TestMessage msg) override {
        if (ProgressLine* progress = console_.settings_.progress) {
            progress->testRetried(test);
        }
        console_.line("  retry       " + shownId(test) + ": " +
                      reporters::shownMessage(msg, "          "));
        Open& open = open_()[test];
        const unsigned int attempts = open.attempts + 1;
        open = Open();
        open.started = happened_;
        open.attempts = attempts;
    }
    void startTestSuite(const TestSuite* suite) override {
        if (ProgressLine* progress = console_.settings_.progress) {
            progress->suiteStarted(suite != nullptr ? reporters::visibleText(suite->getName())
                                                    : "");
        }
    }
    void endTestSuite(const TestSuite* suite) override {
        if (suite == nullptr) {
            return;
        }
        if (ProgressLine* progress = console_.settings_.progress) {
            progress->suiteEnded(reporters::visibleText(suite->getName()));
        }
        const bool ok = suite->succeeded();
        std::string text = "  suite ";
        if (console_.settings_.colours) {
            text += ok ? green : red;
        }
        text += ok ? "passed" : "FAILED";
        text += console_.settings_.colours ? plain : "";
        text += "  " + reporters::visibleText(suite->getName());
        console_.line(text);
    }

private:
    std::map<const Test*, Open>& open_() { return console_.open_; }
    // The suite's name as the console shows it (control characters escaped).
    std::string suiteName() const { return reporters::visibleText(suite_.getName()); }
    // "robot/tests/arith.lua (ArmTest)": its id as --filter takes it, the same as the -j1
    // console's, and the name it gave itself beside.
    std::string shownId(const Test* test) {
        if (test == nullptr) {
            return "";
        }
        auto found = open_().find(test);
        const bool renamed = found != open_().end() && !found->second.name.empty();
        return reporters::shownId(suite_.getName(), test->getKey(),
                                  renamed ? found->second.name : test->getName());
    }
    // The same without the suite: the progress line says its suite apart ("arm :: reach").
    std::string shownAs(const Test* test) {
        if (test == nullptr) {
            return "";
        }
        auto found = open_().find(test);
        const bool renamed = found != open_().end() && !found->second.name.empty();
        return reporters::shownAs(test->getKey(), renamed ? found->second.name : test->getName());
    }

    // A message of `kind`: its word and the state it gives come from the tables.
    void raise(const Test* test, const ResultEvent& event) {
        const TestMessage& msg = event.message;
        const TestStatus status = stateOf(event.kind);
        const std::string label = labelOf(event.kind, event.passed);
        auto found = open_().find(test);
        const std::string text =
            "      " + label + ": " + reporters::shownMessage(msg, "          ");
        if (found == open_().end()) {
            // About the suite itself (a fixture that failed): said at once.
            console_.line("  " + suiteName() + ": " + label + ": " +
                          reporters::shownMessage(msg, "      "));
            return;
        }
        if (status > found->second.status) {
            found->second.status = status;
        }
        if (isFailure(status) && console_.settings_.progress != nullptr) {
            console_.settings_.progress->testFailed(test);
        }
        found->second.lines.push_back(text);
    }

    ParallelConsole& console_;
    const TestSuite& suite_;
    double happened_ = 0;  // when the event being delivered happened (steady seconds)
};

ParallelConsole::ParallelConsole(std::FILE* stream, const TestResultCollector& collector,
                                 ParallelConsoleSettings settings)
    : stream_(stream), collector_(collector), settings_(settings) {}

void ParallelConsole::line(const std::string& text) {
    if (settings_.progress != nullptr) {
        settings_.progress->pause();
    }
    std::fwrite(text.data(), 1, text.size(), stream_);
    std::fputc('\n', stream_);
    if (settings_.progress != nullptr) {
        settings_.progress->resume();  // draws it again, and flushes
    }
}

void ParallelConsole::events(const TestSuite& suite,
                             const std::vector<SuiteEvents::Event>& events) {
    Live live(*this, suite);
    for (const auto& event : events) {
        live.deliver(event);
    }
}

void ParallelConsole::note(const std::string& text) {
    line("robottestingframework-testrunner: " + text);
}

void ParallelConsole::endTestRunner() {
    if (settings_.progress != nullptr) {
        settings_.progress->finish();
    }
    line("");
    if (settings_.summary) {
        line("Summary");
        for (const std::string& text : reporters::summaryLines(collector_)) {
            line(text);
        }
    }
    const std::string closing = reporters::closingLine(collector_);
    if (settings_.colours) {
        line(std::string(collector_.failedCount() > 0 ? red : green) + closing + plain);
    } else {
        line(closing);
    }
    std::fflush(stream_);
}

}  // namespace runner
}  // namespace robottestingframework
