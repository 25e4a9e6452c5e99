#include "reporters/text_reporter.h"

#include <cstdio>

#include "core/text_safety.h"
#include "reporters/summary.h"

namespace robottestingframework {
namespace reporters {

namespace {

// Every message, each with its time ("[1.042 s]", from the run's start): what -v shows on the
// console is the report's whatever -v says.
void appendEvents(std::string& out, const std::vector<ResultEvent>& events,
                  const ReporterSettings& settings, const char* indent) {
    for (std::size_t i = 0; i < events.size(); ++i) {
        const ResultEvent& event = events[i];
        if (!isShown(event, settings.passedChecks) ||
            (!settings.reports && isMessage(event.kind) && !isCheck(event.kind))) {
            continue;
        }
        // A failed check is followed by the failure it makes, with the same words: said once
        // (3 000 failed checks of 5 KB wrote 30 MB, each twice).
        if (isCheck(event.kind) && !event.passed && i + 1 < events.size() &&
            stateOf(events[i + 1].kind) == TestStatus::Failed &&
            events[i + 1].message.getMessage() == event.message.getMessage()) {
            continue;
        }
        char at[32];
        std::snprintf(at, sizeof(at), "[%.3f s] ", event.time);
        const std::string continuation = std::string(indent) + "    ";
        out += indent + std::string(at) + eventLabel(event.kind, event.passed) + ": " +
               shownMessage(event.message, continuation.c_str()) + "\n";
    }
}

void appendOutput(std::string& out, const std::string& output, const char* indent) {
    if (output.empty()) {
        return;
    }
    out += indent;
    out += "output:\n";
    std::size_t begin = 0;
    while (begin < output.size()) {
        std::size_t end = output.find('\n', begin);
        if (end == std::string::npos) {
            end = output.size();
        }
        out += indent;
        out += "  | " + output.substr(begin, end - begin) + "\n";
        begin = end + 1;
    }
}

}  // namespace

void TextReporter::writeDocument(ReportText& text) {
    const bool summary = settings_.summary;
    std::string out = "Robot Testing Framework results\n";
    for (const SuiteRecord& suite : collector_.suites()) {
        out += "\n";
        if (suite.name.empty()) {
            out += "Tests outside any suite\n";
        } else {
            out += "Suite " + visibleText(suite.name) + ": " +
                   (suite.succeeded() ? "passed" : "FAILED") + "  (" + seconds(suite.duration) +
                   ")\n";
            if (!suite.description.empty()) {
                out += "  " + visibleText(suite.description) + "\n";
            }
        }
        appendEvents(out, suite.events, settings_, "  ");
        if (settings_.reports) {
            appendOutput(out, suite.output, "  ");
        }
        for (const TestRecord& test : suite.tests) {
            char word[16];
            std::snprintf(word, sizeof(word), "%-11s", statusWord(test.status));
            out += "  " + std::string(word) + " " + shownAs(test.key, test.name) + "  (" +
                   seconds(test.duration) + ")\n";
            std::vector<ResultEvent> scratch;  // its measurements among its events
            appendEvents(out, test.eventsInOrder(scratch), settings_, "      ");
            if (settings_.reports) {
                appendOutput(out, test.output, "      ");
            }
        }
    }
    if (summary) {
        out += "\nSummary\n";
        for (const std::string& line : summaryLines(collector_)) {
            out += line + "\n";
        }
        out += closingLine(collector_) + "\n";
    }
    // What tests print and say is bytes; the report is a text file whatever they were.
    text += plainText(out);
}

}  // namespace reporters

}  // namespace robottestingframework
