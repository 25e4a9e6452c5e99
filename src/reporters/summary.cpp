#include "reporters/summary.h"

#include <cstdio>

#include "core/text_safety.h"

namespace robottestingframework {
namespace reporters {

const char* colourOf(TestStatus status) {
    if (status == TestStatus::Passed) {
        return colour::green;
    }
    return status == TestStatus::Skipped ? colour::yellow : colour::red;
}

const char* statusWord(TestStatus status) {
    return toLabel(status);
}

std::string eventLabel(ResultEvent::Kind kind, bool passed) {
    return labelOf(kind, passed);
}

std::string messageLine(const TestMessage& msg) {
    std::string text = msg.toString();
    const std::string where = msg.getSourceLocation();
    if (!where.empty()) {
        text += " [" + where + "]";
    }
    return text;
}

std::string diagnosticsBlock(const TestMessage& msg) {
    const std::string lines = msg.getDiagnostics().empty() ? "" : msg.diagnosticsText();
    std::string block;
    std::size_t begin = 0;
    while (begin < lines.size()) {
        std::size_t end = lines.find('\n', begin);
        end = end == std::string::npos ? lines.size() : end;
        block += "\n  " + lines.substr(begin, end - begin);
        begin = end + 1;
    }
    return block;
}

std::string messageText(const TestMessage& msg) {
    return messageLine(msg) + diagnosticsBlock(msg);
}

std::string shownMessage(const TestMessage& msg, const char* continuation) {
    return visibleText(messageText(msg), continuation);
}

std::string traceText(const std::vector<ResultEvent>& events) {
    std::string out;
    for (const ResultEvent& event : events) {
        if (isFailure(stateOf(event.kind))) {
            out += std::string(toString(event.kind)) + ": " + event.message.toString() +
                   diagnosticsBlock(event.message) + "\n";
        }
    }
    return out;
}

std::vector<std::string> outputLines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos) {
            end = text.size();
        }
        lines.push_back("      | " + text.substr(begin, end - begin));
        begin = end + 1;
    }
    return lines;
}

std::string shownAs(const std::string& key, const std::string& name) {
    std::string text;
    appendShownAs(text, key, name);
    return text;
}

void appendShownAs(std::string& text, const std::string& key, const std::string& name) {
    // An absolute path is the name a loader gives a script it loaded (RTF 2.x), not one the test
    // chose: beside the id it would only show the workspace's path.
    // Control characters in either are shown escaped (visibleText): a name must not drive the
    // terminal or fake a line of its own.
    if (key.empty() || name.empty() || key == name || name[0] == '/') {
        text += visibleText(key.empty() ? name : key);
        return;
    }
    text.append(visibleText(key)).append(" (").append(visibleText(name)).append(")");
}

void appendShownId(std::string& text, const std::string& suite, const std::string& key,
                   const std::string& name) {
    if (key.empty() || suite.empty()) {
        appendShownAs(text, key, name);
        return;
    }
    text += visibleText(suite);
    text += '/';
    text += visibleText(key);
    if (!name.empty() && key != name && name[0] != '/') {
        text.append(" (").append(visibleText(name)).append(")");
    }
}

std::string shownId(const std::string& suite, const std::string& key, const std::string& name) {
    std::string text;
    appendShownId(text, suite, key, name);
    return text;
}

std::string seconds(double value) {
    // Printed for every test: integer formatting of the milliseconds is much cheaper than %f.
    const double millis = value * 1000.0 + 0.5;
    if (!(millis >= 0 && millis < 1e15)) {
        char buffer[64];
        std::snprintf(buffer, sizeof(buffer), "%.3f s", value);
        return buffer;
    }
    const auto whole = static_cast<unsigned long long>(millis);
    std::string text = std::to_string(whole / 1000);
    const unsigned fraction = static_cast<unsigned>(whole % 1000);
    text += '.';
    text += static_cast<char>('0' + fraction / 100);
    text += static_cast<char>('0' + fraction / 10 % 10);
    text += static_cast<char>('0' + fraction % 10);
    text += " s";
    return text;
}

std::vector<std::string> summaryLines(const TestResultCollector& collector) {
    std::vector<std::string> lines;
    std::string tests = "  tests:  " + std::to_string(collector.testCount());
    std::string states;
    for (int s = 0; s <= static_cast<int>(TestStatus::Flaky); ++s) {
        const auto status = static_cast<TestStatus>(s);
        const std::size_t count = collector.countOf(status);
        if (count > 0) {
            states += (states.empty() ? "" : ", ") + std::to_string(count) + " " + toString(status);
        }
    }
    if (!states.empty()) {
        tests += " (" + states + ")";
    }
    lines.push_back(tests);
    if (collector.suiteCount() > 0) {
        lines.push_back("  suites: " + std::to_string(collector.suiteCount()) + " (" +
                        std::to_string(collector.passedSuiteCount()) + " passed, " +
                        std::to_string(collector.failedSuiteCount()) + " failed)");
    }
    // A failed fixture counts as a failure in the closing line (closingLine): the summary says
    // the same number and what it is made of (issue 38: "2 failed" here, "3 failed" there).
    if (collector.failedFixtureCount() > 0) {
        const std::size_t tests = collector.failedCount();
        const std::size_t fixtures = collector.failedFixtureCount();
        lines.push_back("  failed: " + std::to_string(tests + fixtures) + " (" +
                        std::to_string(tests) + (tests == 1 ? " test, " : " tests, ") +
                        std::to_string(fixtures) + (fixtures == 1 ? " fixture)" : " fixtures)"));
    }
    lines.push_back("  time:   " + seconds(collector.duration()));
    return lines;
}

std::string closingLine(const TestResultCollector& collector) {
    // A suite whose fixture failed counts once as failed (its tests were not run, and are
    // skipped), so the line says a failure whenever the exit status does.
    std::string line = std::to_string(collector.passedCount()) + " passed, " +
                       std::to_string(collector.failedCount() + collector.failedFixtureCount()) +
                       " failed";
    // Interrupted tests count as failed (the exit status and CTest say so), and the line says
    // how many of them were interrupted, as the summary does (issue 38, friction 6).
    if (collector.countOf(TestStatus::Interrupted) > 0) {
        line += " (" + std::to_string(collector.countOf(TestStatus::Interrupted)) + " interrupted)";
    }
    if (collector.skippedCount() > 0) {
        line += ", " + std::to_string(collector.skippedCount()) + " skipped";
    }
    if (collector.countOf(TestStatus::Flaky) > 0) {
        line += ", " + std::to_string(collector.countOf(TestStatus::Flaky)) + " flaky";
    }
    return line;
}

}  // namespace reporters
}  // namespace robottestingframework
