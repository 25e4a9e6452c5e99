#include "reporters/html_reporter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string_view>

#include "core/text_safety.h"
#include "reporters/history_strip.h"
#include "reporters/html_page_assets.h"
#include "reporters/summary.h"

namespace robottestingframework {
namespace reporters {

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6f", value);
    return text;
}

const char* label(const ResultEvent& event) {
    return nameOf(event.kind, event.passed);
}

// The message as the page shows it, the place it came from apart.
std::string messageData(const ResultEvent& event) {
    const TestMessage& msg = event.message;
    std::string text = msg.getMessage();
    if (!msg.getDetail().empty()) {
        text += ": " + msg.getDetail();
    }
    std::string out = "{\"label\":" + jsonString(label(event)) + ",\"text\":" + jsonString(text) +
                      ",\"time\":" + number(event.time);
    if (!msg.getSourceFileName().empty()) {
        out += ",\"at\":" + jsonString(msg.getSourceFileName() + ":" +
                                       std::to_string(msg.getSourceLineNumber()));
    }
    if (!msg.getDiagnostics().empty()) {
        out += ",\"diagnostics\":" + jsonString(msg.diagnosticsText());
    }
    if (isFailure(stateOf(event.kind)) || (isCheck(event.kind) && !event.passed)) {
        out += ",\"problem\":true";
    }
    return out + "}";
}

// Cut on a character boundary, never inside a UTF-8 sequence.
std::string capped(const std::string& text, std::size_t& cut) {
    const std::string valid = validUtf8(text);
    if (valid.size() <= HtmlReporter::outputCap) {
        cut = 0;
        return valid;
    }
    std::size_t end = HtmlReporter::outputCap;
    while (end > 0 && (static_cast<unsigned char>(valid[end]) & 0xC0) == 0x80) {
        --end;
    }
    cut = valid.size() - end;
    return valid.substr(0, end);
}

// The page's text with `name` (as "@NAME@") replaced by `value`, once.
void fill(std::string& page, const std::string& name, const std::string& value) {
    const std::string mark = "@" + name + "@";
    const std::size_t at = page.find(mark);
    if (at != std::string::npos) {
        page.replace(at, mark.size(), value);
    }
}

// A measurement event as the page's table and plots read it.
std::string measurementData(const ResultEvent& event) {
    const Measurement& m = *event.measurement;
    std::string out = "{\"name\":" + jsonString(m.name) + ",\"value\":" + formatNumber(m.value) +
                      ",\"unit\":" + jsonString(m.unit);
    if (m.low) {
        out += ",\"low\":" + formatNumber(*m.low);
    }
    if (m.high) {
        out += ",\"high\":" + formatNumber(*m.high);
    }
    return out + ",\"passed\":" + (event.passed ? "true" : "false") +
           ",\"rep\":" + std::to_string(event.repetition) + "}";
}

// A test's (or a suite's) measurements (a table on the page, a plot per name) and attachments
// (links; images inline).
void appendMeasurementsAndAttachments(std::string& out, const std::vector<ResultEvent>& events) {
    std::string measurements;
    std::string attachments;
    for (const ResultEvent& event : events) {
        if (isMeasurement(event)) {
            measurements += (measurements.empty() ? "" : ",") + measurementData(event);
        } else if (isAttachment(event)) {
            const Attachment& a = *event.attachment;
            attachments += std::string(attachments.empty() ? "" : ",") +
                           "{\"name\":" + jsonString(a.originalName) +
                           ",\"path\":" + jsonString(a.path) +
                           ",\"description\":" + jsonString(a.description) +
                           ",\"size\":" + std::to_string(a.size) + "}";
        }
    }
    if (!measurements.empty()) {
        out += ",\"measurements\":[" + measurements + "]";
    }
    if (!attachments.empty()) {
        out += ",\"attachments\":[" + attachments + "]";
    }
}

}  // namespace

// One test's data. The page's per-test sections (report.js: testSections) read it; a part of
// the report that adds a section adds its fields here.
std::string HtmlReporter::testData(const TestRecord& test, const SuiteRecord& suite) const {
    // Its measurements among its events, as events: what this format lists.
    std::vector<ResultEvent> scratch;
    const std::vector<ResultEvent>& events = test.eventsInOrder(scratch);
    std::string out = "{\"id\":" + std::to_string(test.id);
    // The name is its id in its suite; "shown" the name it gave itself, beside it.
    const std::string& name = test.reportName();
    out += ",\"name\":" + jsonString(name.empty() ? "unnamed test" : name);
    if (!test.shownName().empty()) {
        out += ",\"shown\":" + jsonString(test.shownName());
    }
    if (!test.key.empty()) {
        out += ",\"fullId\":" + jsonString(suite.name + "/" + test.key);
        const auto facts = settings_.testFacts.find(suite.name + "/" + test.key);
        if (facts != settings_.testFacts.end()) {
            const TestFacts& known = facts->second;
            if (!known.type.empty()) {
                out += ",\"type\":" + jsonString(known.type);
            }
            if (!known.param.empty()) {
                out += ",\"param\":" + jsonString(known.param);
            }
            if (!known.tags.empty()) {
                out += ",\"tags\":[";
                for (std::size_t i = 0; i < known.tags.size(); ++i) {
                    out += (i == 0 ? "" : ",") + jsonString(known.tags[i]);
                }
                out += "]";
            }
        }
    }
    out += ",\"state\":" + jsonString(toString(test.status));
    out += ",\"start\":" + number(test.start);
    out += ",\"duration\":" + number(test.duration);
    if (!test.description.empty()) {
        out += ",\"description\":" + jsonString(test.description);
    }
    if (settings_.history) {
        const auto strip = settings_.history->find(suite.name + "/" + name);
        if (strip != settings_.history->end()) {
            out += ",\"history\":" + historyStripData(strip->second);
        }
    }
    // Why it failed, for its row: the first problem's message.
    if (const ResultEvent* reason = test.reason()) {
        if (isFailure(test.status)) {
            out += ",\"reason\":" +
                   jsonString(label(*reason) + std::string(": ") + messageText(reason->message));
        }
    }
    out += ",\"messages\":[";
    bool firstMessage = true;
    for (std::size_t i = 0; i < events.size(); ++i) {
        const ResultEvent& event = events[i];
        if (!isShown(event, settings_.passedChecks)) {
            continue;
        }
        if (carriesAnything(event.kind)) {
            continue;  // in their own table and links
        }
        // A failed check is followed by the failure it makes, with the same words: said once,
        // as the text report and the console say it.
        if (isFailedCheck(event) && i + 1 < events.size() &&
            stateOf(events[i + 1].kind) == TestStatus::Failed &&
            events[i + 1].message.getMessage() == event.message.getMessage()) {
            continue;
        }
        out += (firstMessage ? "" : ",") + messageData(event);
        firstMessage = false;
    }
    out += "]";
    appendMeasurementsAndAttachments(out, events);
    if (!test.attempts.empty()) {
        out += ",\"attempts\":[";
        for (std::size_t i = 0; i < test.attempts.size(); ++i) {
            const TestAttempt& attempt = test.attempts[i];
            out += std::string(i == 0 ? "" : ",") +
                   "{\"state\":" + jsonString(toString(attempt.status)) +
                   ",\"duration\":" + number(attempt.duration) +
                   ",\"message\":" + jsonString(messageText(attempt.message));
            appendMeasurementsAndAttachments(out, test.measurementEvents(attempt.measurements));
            out += "}";
        }
        out += "]";
    }
    if (!test.output.empty()) {
        std::size_t cut = 0;
        out += ",\"output\":" + jsonString(capped(test.output, cut));
        if (cut > 0) {
            out += ",\"outputCut\":" + std::to_string(cut);
        }
    }
    return out + "}";
}

// One suite's data: its times (the fixture's setup runs from its start to its first test's,
// its teardown from its last test's end to its own), its messages and its tests.
std::string HtmlReporter::suiteData(const SuiteRecord& suite) const {
    WholeReportText text;
    writeSuiteData(text, suite);
    return text.take();
}

void HtmlReporter::writeSuiteData(ReportText& text, const SuiteRecord& suite) const {
    double firstStart = suite.start + suite.duration;
    double lastEnd = suite.start;
    for (const TestRecord& test : suite.tests) {
        if (test.duration > 0 || test.status != TestStatus::Skipped) {
            firstStart = std::min(firstStart, test.start);
            lastEnd = std::max(lastEnd, test.start + test.duration);
        }
    }
    const bool anyRan = lastEnd > suite.start || firstStart < suite.start + suite.duration;
    const double setup = anyRan ? std::max(0.0, firstStart - suite.start) : suite.duration;
    const double teardown = anyRan ? std::max(0.0, suite.start + suite.duration - lastEnd) : 0.0;
    std::string out = "{\"name\":" + jsonString(suite.name) + ",\"start\":" + number(suite.start) +
                      ",\"duration\":" + number(suite.duration) + ",\"setup\":" + number(setup) +
                      ",\"teardown\":" + number(teardown);
    if (suite.fixtureFailed) {
        out += ",\"problems\":" + jsonString(traceText(suite.events));
    }
    out += ",\"messages\":[";
    bool firstMessage = true;
    for (const ResultEvent& event : suite.events) {
        if (isAttachment(event)) {
            continue;  // linked apart (a process fixture's logs)
        }
        out += (firstMessage ? "" : ",") + messageData(event);
        firstMessage = false;
    }
    out += "]";
    appendMeasurementsAndAttachments(out, suite.events);
    if (!suite.output.empty()) {
        std::size_t cut = 0;
        out += ",\"output\":" + jsonString(capped(suite.output, cut));
    }
    out += ",\"tests\":[";
    text += out;
    bool firstTest = true;
    for (const TestRecord& test : suite.tests) {
        text += firstTest ? "\n" : ",\n";
        firstTest = false;
        text += testData(test, suite);
    }
    text += "]}";
}

// The page around the data, the data written into it a test at a time: the runner hands it on
// to the file as it goes.
void HtmlReporter::writeDocument(ReportText& out) {
    const std::time_t started = std::chrono::system_clock::to_time_t(collector_.startedAt());
    std::tm utc{};
    gmtime_r(&started, &utc);
    char when[40];
    std::strftime(when, sizeof(when), "%Y-%m-%d %H:%M:%S UTC", &utc);

    std::string data = "{\"started\":" + jsonString(when);
    data += ",\"duration\":" + number(collector_.duration());
    data += ",\"suitesRun\":" + std::to_string(collector_.suiteCount());
    data += ",\"suitesFailed\":" + std::to_string(collector_.failedSuiteCount());
    data += ",\"facts\":[";
    for (std::size_t i = 0; i < settings_.runFacts.size(); ++i) {
        data += std::string(i == 0 ? "" : ",") + "[" + jsonString(settings_.runFacts[i].first) +
                "," + jsonString(settings_.runFacts[i].second) + "]";
    }
    data += "]";
    data += ",\"counts\":{\"total\":" + std::to_string(collector_.testCount());
    for (TestStatus status :
         {TestStatus::Passed, TestStatus::Skipped, TestStatus::Failed, TestStatus::Error,
          TestStatus::Crashed, TestStatus::TimedOut, TestStatus::Interrupted, TestStatus::Flaky}) {
        data +=
            "," + jsonString(toString(status)) + ":" + std::to_string(collector_.countOf(status));
    }
    data += "}";
    // The shared worlds, each a lane of the timeline: start, ready, stop, failure.
    data += ",\"worlds\":[";
    bool firstWorld = true;
    for (const WorldRecord& world : collector_.worlds()) {
        data += std::string(firstWorld ? "" : ",") + "{\"name\":" + jsonString(world.name) +
                ",\"users\":" + jsonString(world.users) + ",\"start\":" + number(world.start) +
                ",\"ready\":" + number(world.ready) + ",\"stop\":" + number(world.stop) +
                ",\"failed\":" + number(world.failed) + ",\"reason\":" + jsonString(world.reason) +
                "}";
        firstWorld = false;
    }
    data += "],\"suites\":[";

    // The style and script first; the data, test text that may hold anything ("@REPORT_JS@"
    // too), goes where "@REPORT_DATA@" is and is never searched.
    std::string page = htmlReportPage();
    fill(page, "REPORT_CSS", htmlReportStyle());
    fill(page, "REPORT_JS", htmlReportScript());
    const std::string mark = "@REPORT_DATA@";
    const std::size_t at = page.find(mark);
    if (at == std::string::npos) {
        out += page;
        return;
    }
    out += std::string_view(page).substr(0, at);
    out += data;
    bool firstSuite = true;
    for (const SuiteRecord& suite : collector_.suites()) {
        out += firstSuite ? "\n" : ",\n";
        firstSuite = false;
        writeSuiteData(out, suite);
    }
    out += "]}";
    out += std::string_view(page).substr(at + mark.size());
}

}  // namespace reporters
}  // namespace robottestingframework
