#include <robottestingframework/TextOutputter.h>

#include <cstdio>

#include "atomic_file.h"
#include "summary.h"

namespace robottestingframework {

namespace {

void appendEvents(std::string& out, const std::vector<ResultEvent>& events, bool verbose,
                  const char* indent) {
    using Kind = ResultEvent::Kind;
    for (const ResultEvent& event : events) {
        if (!verbose && (event.kind == Kind::Report || event.kind == Kind::Check)) {
            continue;
        }
        out += indent + reporters::eventLabel(event.kind, event.passed) + ": " +
               reporters::messageText(event.message) + "\n";
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

TextOutputter::TextOutputter(TestResultCollector& collector, bool verbose)
    : collector_(collector), verbose_(verbose) {}

std::string TextOutputter::text(bool summary) const {
    std::string out = "Robot Testing Framework results\n";
    for (const SuiteRecord& suite : collector_.suites()) {
        out += "\n";
        if (suite.name.empty()) {
            out += "Tests outside any suite\n";
        } else {
            out += "Suite " + suite.name + ": " + (suite.succeeded() ? "passed" : "FAILED") +
                   "  (" + reporters::seconds(suite.duration) + ")\n";
            if (!suite.description.empty()) {
                out += "  " + suite.description + "\n";
            }
        }
        appendEvents(out, suite.events, verbose_, "  ");
        if (verbose_) {
            appendOutput(out, suite.output, "  ");
        }
        for (const TestRecord& test : suite.tests) {
            char word[16];
            std::snprintf(word, sizeof(word), "%-11s", reporters::statusWord(test.status));
            out += "  " + std::string(word) + " " + test.name + "  (" +
                   reporters::seconds(test.duration) + ")\n";
            appendEvents(out, test.events, verbose_, "      ");
            if (verbose_) {
                appendOutput(out, test.output, "      ");
            }
        }
    }
    if (summary) {
        out += "\nSummary\n";
        for (const std::string& line : reporters::summaryLines(collector_)) {
            out += line + "\n";
        }
        out += reporters::closingLine(collector_) + "\n";
    }
    return out;
}

bool TextOutputter::write(std::string filename, bool summary, TestMessage* error) {
    return reporters::writeReport(filename, text(summary), error);
}

}  // namespace robottestingframework
