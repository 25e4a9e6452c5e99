#include "reporters/tap_reporter.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <robottestingframework/Test.h>
#include <robottestingframework/TestSuite.h>

#include "core/text_safety.h"
#include "reporters/summary.h"

namespace robottestingframework {
namespace reporters {

namespace {

std::uint64_t idOf(const Test* test) {
    return test != nullptr ? test->getId() : 0;
}

// A description: one line, with "#" and "\" escaped so no directive is read into it.
std::string description(const std::string& text) {
    std::string out;
    for (const char c : validUtf8(text)) {
        if (c == '\\' || c == '#') {
            out += '\\';
            out += c;
        } else if (c == '\n' || c == '\r') {
            out += ' ';
        } else {
            out += c;
        }
    }
    return out;
}

// A directive's reason runs to the end of the line.
std::string oneLine(const std::string& text) {
    std::string out = validUtf8(text);
    std::replace(out.begin(), out.end(), '\n', ' ');
    std::replace(out.begin(), out.end(), '\r', ' ');
    return out;
}

const char* severity(TestStatus status) {
    switch (status) {
        case TestStatus::Failed:
            return "fail";
        case TestStatus::Error:
            return "error";
        case TestStatus::Crashed:
            return "crash";
        case TestStatus::TimedOut:
            return "timeout";
        case TestStatus::Interrupted:
            return "interrupted";
        default:
            return "comment";
    }
}

// A message's diagnostics as a YAML map, each "key: value" line after `indent` (keys and
// values as JSON literals, which YAML reads as they are: the program's YAML was read, so what
// is written here is always valid); "" without any.
std::string diagnosticsMap(const TestMessage& msg, const std::string& indent) {
    std::string text;
    std::vector<std::string> seen;  // a key given twice is written once (YAML refuses repeats)
    for (const auto& [key, value] : msg.getDiagnostics()) {
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
            continue;
        }
        seen.push_back(key);
        // A key of letters, digits and _ - . as it is (`found:`), any other quoted.
        const bool plain = !key.empty() && std::isalpha(static_cast<unsigned char>(key[0])) &&
                           std::all_of(key.begin(), key.end(), [](char c) {
                               return std::isalnum(static_cast<unsigned char>(c)) || c == '_' ||
                                      c == '-' || c == '.';
                           });
        text += indent + (plain ? key : jsonString(key)) + ": " + jsonString(value) + "\n";
    }
    return text;
}

// One item of a test's "messages:" list, after its "    - ": the line quoted, or when the
// message has diagnostics, a map of its `text` and `diagnostics`.
std::string messageItem(const std::string& line, const TestMessage& msg) {
    if (msg.getDiagnostics().empty()) {
        return jsonString(line) + "\n";
    }
    return "text: " + jsonString(line) + "\n      diagnostics:\n" + diagnosticsMap(msg, "        ");
}

// A test's reports and checks as YAML lines ("  messages:" and one item each), or nothing.
std::string messageLines(const std::vector<std::string>& messages) {
    if (messages.empty()) {
        return "";
    }
    std::string text = "  messages:\n";
    for (const std::string& message : messages) {
        text += "    - " + message;
    }
    return text;
}

// The attachments of a test or suite as YAML (empty without any).
std::string attachmentLines(const std::string& attachments) {
    return attachments.empty() ? std::string() : "  attachments:\n" + attachments;
}

// YAML diagnostics for a failed point, up to its end ("  ...", which follows what else the
// point says); strings as JSON literals, which YAML reads as they are.
std::string diagnostics(TestStatus status, const TestMessage& reason, const std::string& output) {
    std::string text = "  ---\n";
    text += "  message: " + jsonString(reason.getMessage()) + "\n";
    text += std::string("  severity: ") + severity(status) + "\n";
    if (!reason.getDetail().empty()) {
        text += "  data:\n    detail: " + jsonString(reason.getDetail()) + "\n";
    }
    if (!reason.getDiagnostics().empty()) {
        text += "  diagnostics:\n" + diagnosticsMap(reason, "    ");
    }
    if (!reason.getSourceFileName().empty()) {
        text += "  at:\n    file: " + jsonString(reason.getSourceFileName()) +
                "\n    line: " + std::to_string(reason.getSourceLineNumber()) + "\n";
    }
    if (!output.empty()) {
        text += "  output: " + jsonString(output) + "\n";
    }
    return text;
}

// A test's measurements as the YAML list items of its point.
void measurementLines(const MeasurementList& measurements, std::string& text) {
    for (const MeasurementRecord& measured : measurements) {
        text += "    - name: " + jsonString(measured.name()) +
                "\n      value: " + formatNumber(measured.value) +
                "\n      unit: " + jsonString(measured.unit()) + "\n";
        if (measured.hasLow) {
            text += "      low: " + formatNumber(measured.low) + "\n";
        }
        if (measured.hasHigh) {
            text += "      high: " + formatNumber(measured.high) + "\n";
        }
        text += std::string("      passed: ") + (measured.passed ? "true" : "false") + "\n";
    }
}

}  // namespace

void TapReporter::closeTest(std::vector<Block>& blocks, const OpenTest& test) {
    Block& block = blocks.back();
    const std::string number = std::to_string(++block.points);
    const std::string name = description(test.name.empty() ? "unnamed test" : test.name);
    const bool extra = !test.messages.empty() || test.measurements > 0 || !test.attachments.empty();
    // The point and its YAML up to where its measurements go: they are written from the
    // collector's records with the file (a mark here), not held as text for the whole run.
    std::string head;
    bool yaml = true;
    if (test.status == TestStatus::Passed && test.retries > 0) {
        // Flaky: passed on a later attempt. TAP has no such directive; the YAML says it.
        head = "ok " + number + " - " + name +
               "\n  ---\n  flaky: true\n  retries: " + std::to_string(test.retries) + "\n";
    } else if (!isFailure(test.status)) {
        head = "ok " + number + " - " + name;
        if (test.status == TestStatus::Skipped) {
            head += " # SKIP " + oneLine(test.reason.toString());
        }
        head += "\n";
        yaml = extra;
        if (yaml) {
            head += "  ---\n";
        }
    } else {
        block.failed = true;
        head = "not ok " + number + " - " + name + "\n" +
               diagnostics(test.status, test.reason, test.output);
    }
    head += messageLines(test.messages);
    if (test.measurements > 0) {
        head += "  measurements:\n";
    }
    block.body += head;
    if (test.measurements > 0) {
        block.body.markLines(test.id);
    }
    if (yaml) {
        block.body += attachmentLines(test.attachments) + "  ...\n";
    }
}

void TapReporter::closeSuite(std::vector<Block>& blocks, std::vector<std::string>& bailOuts) {
    Block suite = std::move(blocks.back());
    blocks.pop_back();
    Block& parent = blocks.back();
    const std::string name = description(suite.name.empty() ? "unnamed suite" : suite.name);
    parent.body += "# Subtest: " + name + "\n";
    // Moved, not copied: the body is most of the report.
    parent.body.appendNested(std::move(suite.body));
    parent.body += "    1.." + std::to_string(suite.points) + "\n";
    const std::string number = std::to_string(++parent.points);
    const std::string extra = attachmentLines(suite.attachments);
    if (suite.fixtureProblems.empty() && !suite.failed) {
        parent.body += "ok " + number + " - " + name + "\n";
        if (!extra.empty()) {
            parent.body += "  ---\n" + extra + "  ...\n";
        }
        return;
    }
    parent.failed = true;
    parent.body += "not ok " + number + " - " + name + "\n";
    if (!suite.fixtureProblems.empty()) {
        const TestMessage& first = suite.fixtureProblems.front();
        parent.body += diagnostics(TestStatus::Error, first, "") + extra + "  ...\n";
        bailOuts.push_back(oneLine("fixture of " + suite.name + " failed: " + first.toString()));
    } else if (!extra.empty()) {
        parent.body += "  ---\n" + extra + "  ...\n";
    }
}

void TapReporter::writeDocument(ReportText& out) {
    // Whatever is still open (a run cut short) is closed on copies: events may follow. A run
    // that ended has nothing open, and its body is written as it is.
    const std::vector<Block>* blocks = &blocks_;
    const std::vector<std::string>* bailOuts = &bailOuts_;
    std::vector<Block> closedBlocks;
    std::vector<std::string> closedBailOuts;
    if (!open_.empty() || blocks_.size() > 1) {
        closedBlocks = blocks_;
        closedBailOuts = bailOuts_;
        for (auto it = open_.rbegin(); it != open_.rend(); ++it) {
            OpenTest test = *it;
            if (!isFailure(test.status)) {
                test.status = TestStatus::Interrupted;
                test.reason = TestMessage("interrupted: the run ended before the test did");
            }
            closeTest(closedBlocks, test);
        }
        while (closedBlocks.size() > 1) {
            closeSuite(closedBlocks, closedBailOuts);
        }
        blocks = &closedBlocks;
        bailOuts = &closedBailOuts;
    }
    out += "TAP version 14\n1.." + std::to_string(blocks->front().points) + "\n";
    // The tests that measured something, by id: their points' marks get their measurements.
    std::unordered_map<std::uint64_t, const TestRecord*> measured;
    for (const SuiteRecord& suite : collector_.suites()) {
        for (const TestRecord& test : suite.tests) {
            if (!test.measurements.empty()) {
                measured[test.id] = &test;
            }
        }
    }
    blocks->front().body.writeTo(out, [&measured](std::uint64_t id, std::string& text) {
        const auto found = measured.find(id);
        if (found != measured.end()) {
            measurementLines(found->second->measurements, text);
        }
    });
    // After every result, so none is lost: a consumer stops reading at a bail-out.
    if (!bailOuts->empty()) {
        out += "Bail out! " + bailOuts->front() + "\n";
    }
}

void TapReporter::startTestSuite(const TestSuite* suite) {
    Block block;
    block.name = suite != nullptr ? suite->getName() : "";
    blocks_.push_back(std::move(block));
}

void TapReporter::endTestSuite(const TestSuite* /*suite*/) {
    if (blocks_.size() > 1) {
        closeSuite(blocks_, bailOuts_);
    }
}

void TapReporter::renameTest(const Test* test, const std::string& name) {
    // A test with an id is described by it (docs/reference/test-ids.md), whatever it calls itself.
    if (test != nullptr && !test->getKey().empty()) {
        return;
    }
    for (auto it = open_.rbegin(); it != open_.rend(); ++it) {
        if (it->id == idOf(test)) {
            it->name = name;
            return;
        }
    }
}

void TapReporter::startTest(const Test* test) {
    const std::string name = test == nullptr          ? ""
                             : test->getKey().empty() ? test->getName()
                                                      : test->getKey();
    OpenTest open{idOf(test), name, TestStatus::Passed, {}, {}, 0, {}, {}, {}};
    if (test != nullptr && retrying_ != 0 && idOf(test) == retrying_) {
        open.retries = retryCount_;
    }
    retrying_ = 0;
    open_.push_back(std::move(open));
}

void TapReporter::endTest(const Test* test) {
    for (std::size_t i = open_.size(); i > 0; --i) {
        if (open_[i - 1].id == idOf(test)) {
            OpenTest done = std::move(open_[i - 1]);
            open_.erase(open_.begin() + static_cast<std::ptrdiff_t>(i - 1));
            last_ = {done.id,
                     blocks_.size(),
                     blocks_.back().body.size(),
                     blocks_.back().points,
                     blocks_.back().failed,
                     done.retries};
            closeTest(blocks_, done);
            return;
        }
    }
}

void TapReporter::note(const Test* test, const ResultEvent& event) {
    const TestMessage& msg = event.message;
    const TestStatus state = stateOf(event.kind);
    // Reports and checks are kept whatever -v says, each with its time from the run's start.
    const bool message = isMessage(event.kind) && isShown(event, settings_.passedChecks);
    std::string line;
    if (message) {
        char at[32];
        std::snprintf(at, sizeof(at), "[%.3f s] ", collector_.duration());
        line = at + std::string(labelOf(event.kind, event.passed)) + ": " + messageLine(msg);
    }
    for (auto it = open_.rbegin(); it != open_.rend(); ++it) {
        if (it->id == idOf(test)) {
            if (state > it->status) {
                it->status = state;
                it->reason = msg;
            }
            if (message) {
                it->messages.push_back(messageItem(line, msg));
            }
            return;
        }
    }
    // Not a test's own: a fixture's, as the collector counts it. Its reports are comments.
    if (message) {
        blocks_.back().body += "# " + oneLine(line) + "\n";
        for (const auto& [key, value] : msg.getDiagnostics()) {
            blocks_.back().body += "#   " + oneLine(key + ": " + value) + "\n";
        }
    }
    if (isFailure(state) && blocks_.size() > 1) {
        blocks_.back().fixtureProblems.push_back(msg);
    }
}

void TapReporter::onEvent(const RunEvent& event) {
    ResultEvent scratch;
    const ResultEvent& data = shownEvent(event.data, scratch);
    if (isSaid(data) || isMessage(data.kind)) {
        note(event.test, data);
    } else {
        TestListener::onEvent(event);
    }
}
void TapReporter::retryTest(const Test* test, TestMessage /*msg*/) {
    if (test == nullptr || last_.id == 0 || last_.id != idOf(test) ||
        blocks_.size() != last_.depth) {
        return;
    }
    // The failed attempt's point is taken back: the test gets one point, its last attempt's.
    Block& block = blocks_.back();
    block.body.truncate(last_.bodySize);
    block.points = last_.points;
    block.failed = last_.failed;
    retrying_ = last_.id;
    retryCount_ = last_.retries + 1;
    last_ = LastPoint();
}

TapReporter::OpenTest* TapReporter::openTest(const Test* test) {
    for (auto it = open_.rbegin(); it != open_.rend(); ++it) {
        if (it->id == idOf(test)) {
            return &*it;
        }
    }
    return nullptr;
}

void TapReporter::addMeasurement(const Test* test, const Measurement& /*measurement*/,
                                 bool /*passed*/) {
    // Counted only: the collector keeps the measurement, and the file is written from it.
    if (OpenTest* open = openTest(test)) {
        ++open->measurements;
    }
}

void TapReporter::addAttachment(const Test* test, const Attachment& attachment) {
    OpenTest* open = openTest(test);
    // Not a test's: a fixture's (a process's log), written with its suite's point.
    if (open == nullptr && blocks_.size() <= 1) {
        return;
    }
    std::string& items = open != nullptr ? open->attachments : blocks_.back().attachments;
    items += "    - name: " + jsonString(attachment.originalName) +
             "\n      path: " + jsonString(attachment.path) +
             "\n      description: " + jsonString(attachment.description) +
             "\n      contentType: " + jsonString(attachment.contentType()) +
             "\n      size: " + std::to_string(attachment.size) + "\n";
}

void TapReporter::addOutput(const Test* test, const std::string& text) {
    for (auto it = open_.rbegin(); it != open_.rend(); ++it) {
        if (it->id == idOf(test)) {
            it->output += text;
            return;
        }
    }
}

}  // namespace reporters
}  // namespace robottestingframework
