#include "reporters/json_reporter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "core/text_safety.h"
#include "reporters/summary.h"

namespace robottestingframework {
namespace reporters {

namespace {

// The key of the runner's extensions in every "extra" object, namespaced as the CTRF
// specification recommends (4.6.1: an owner's prefix and a delimiter, the same key throughout
// the document). report_reader.cpp reads it, and the "rtf" of earlier versions.
const char* const extension = "\"robotology.rtf\"";

// CTRF's five statuses; the state itself is kept in extra["robotology.rtf"].state.
const char* ctrfStatus(TestStatus status) {
    switch (status) {
        case TestStatus::Passed:
        case TestStatus::Flaky:  // CTRF: passed, with "flaky": true
            return "passed";
        case TestStatus::Skipped:
            return "skipped";
        case TestStatus::Interrupted:
            return "other";
        default:
            return "failed";
    }
}

long long milliseconds(double seconds) {
    return std::llround(seconds * 1000.0);
}

std::string rfc3339(long long epochMs) {
    const std::time_t seconds = static_cast<std::time_t>(epochMs / 1000);
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char text[96];
    std::snprintf(text, sizeof(text), "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900,
                  utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec,
                  static_cast<int>(epochMs % 1000));
    return text;
}

std::string lines(const std::string& text) {
    std::string out = "[";
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos) {
            end = text.size();
        }
        out += (begin == 0 ? "" : ",") + jsonString(text.substr(begin, end - begin));
        begin = end + 1;
    }
    return out + "]";
}

// A message's diagnostics as a member of its object, `,"diagnostics":{"key":"value",...}` in
// their order (a key given twice keeps its first value, as JSON readers differ on repeats);
// "" without any.
std::string diagnosticsMember(const TestMessage& msg) {
    std::string out;
    std::vector<std::string> seen;
    for (const auto& [key, value] : msg.getDiagnostics()) {
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
            continue;
        }
        seen.push_back(key);
        out += std::string(out.empty() ? "" : ",") + jsonString(key) + ":" + jsonString(value);
    }
    return out.empty() ? out : ",\"diagnostics\":{" + out + "}";
}

// The messages of `events` as [{"kind","message","diagnostics","time"}]: reports and checks (passed
// ones when `passedChecks`), and with `all` every other kind too (a fixture's failures).
std::string messageList(const std::vector<ResultEvent>& events, long long origin, bool passedChecks,
                        bool all) {
    std::string out;
    for (const ResultEvent& event : events) {
        if ((!isMessage(event.kind) && !all) || !isShown(event, passedChecks)) {
            continue;
        }
        out += std::string(out.empty() ? "" : ",") +
               "{\"kind\":" + jsonString(eventLabel(event.kind, event.passed)) +
               ",\"message\":" + jsonString(event.message.toString()) +
               diagnosticsMember(event.message) +
               ",\"time\":" + std::to_string(origin + milliseconds(event.time)) + "}";
    }
    return "[" + out + "]";
}

// CTRF's own attachments of a test: name, contentType and path (relative to the report's
// folder), the description in the extension.
std::string attachmentsOf(const std::vector<ResultEvent>& events) {
    std::string out;
    for (const ResultEvent& event : events) {
        if (!isAttachment(event)) {
            continue;
        }
        const Attachment& attachment = *event.attachment;
        out += std::string(out.empty() ? "" : ",") +
               "{\"name\":" + jsonString(attachment.originalName) +
               ",\"contentType\":" + jsonString(attachment.contentType()) +
               ",\"path\":" + jsonString(attachment.path) + ",\"extra\":{" + extension +
               ":{\"description\":" + jsonString(attachment.description) +
               ",\"size\":" + std::to_string(attachment.size) + "}}}";
    }
    return out;
}

// extra["robotology.rtf"].measurements: each measurement of a test in order, with its limits,
// whether it passed them, and its repetition (0: the test runs once).
std::string measurementsOf(const std::vector<ResultEvent>& events) {
    std::string out;
    for (const ResultEvent& event : events) {
        if (!isMeasurement(event)) {
            continue;
        }
        const Measurement& measurement = *event.measurement;
        out += std::string(out.empty() ? "" : ",") + "{\"name\":" + jsonString(measurement.name) +
               ",\"value\":" + formatNumber(measurement.value) +
               ",\"unit\":" + jsonString(measurement.unit);
        if (measurement.low) {
            out += ",\"low\":" + formatNumber(*measurement.low);
        }
        if (measurement.high) {
            out += ",\"high\":" + formatNumber(*measurement.high);
        }
        out += std::string(",\"passed\":") + (event.passed ? "true" : "false") +
               ",\"repetition\":" + std::to_string(event.repetition) + "}";
    }
    return out;
}

// `testId` is the test's place in the run ("suite.test", from 1): the same in every run of
// the same suites, and apart for two tests of one name. `executionId` is the id its events
// carried in this run.
void appendTest(ReportText& out, const TestRecord& test, const SuiteRecord& suite,
                const std::string& testId, long long origin, bool passedChecks) {
    // Its measurements among its events, as events: what this format lists.
    std::vector<ResultEvent> scratch;
    const std::vector<ResultEvent>& events = test.eventsInOrder(scratch);
    const long long start = origin + milliseconds(test.start);
    out += "{\"testId\":\"" + testId + "\"";
    out += ",\"executionId\":\"" + std::to_string(test.id) + "\"";
    // The name is the test's id in its suite, the same in every workspace
    // (docs/reference/test-ids.md); extra["robotology.rtf"]: id is its whole id, name the name the
    // test gave itself.
    const std::string& name = test.reportName();
    out += ",\"name\":" + jsonString(name.empty() ? "unnamed test" : name);
    out += ",\"status\":\"" + std::string(ctrfStatus(test.status)) + "\"";
    out += ",\"duration\":" + std::to_string(milliseconds(test.duration));
    out += ",\"start\":" + std::to_string(start);
    out += ",\"stop\":" + std::to_string(start + milliseconds(test.duration));
    out += ",\"rawStatus\":" + jsonString(toString(test.status));
    if (!suite.name.empty()) {
        out += ",\"suite\":[" + jsonString(suite.name) + "]";
    }
    if (const ResultEvent* reason = test.reason()) {
        out += ",\"message\":" + jsonString(reason->message.toString());
        const std::string trace = traceText(events);
        if (!trace.empty()) {
            out += ",\"trace\":" + jsonString(trace);
        }
        if (!reason->message.getSourceFileName().empty()) {
            out += ",\"filePath\":" + jsonString(reason->message.getSourceFileName());
            out += ",\"line\":" + std::to_string(reason->message.getSourceLineNumber());
        }
    }
    if (!test.output.empty()) {
        out += ",\"stdout\":" + lines(test.output);
    }
    out += ",\"retries\":" + std::to_string(test.attempts.size());
    if (!test.attempts.empty()) {
        // The earlier failed attempts (--retries), as CTRF has them: one entry per attempt
        // before the final one, numbered from 1, each with its own state in the extension.
        out += ",\"retryAttempts\":[";
        for (std::size_t i = 0; i < test.attempts.size(); ++i) {
            const TestAttempt& attempt = test.attempts[i];
            out += std::string(i == 0 ? "" : ",") + "{\"attempt\":" + std::to_string(i + 1) +
                   ",\"status\":\"" + ctrfStatus(attempt.status) + "\"" +
                   ",\"duration\":" + std::to_string(milliseconds(attempt.duration)) +
                   ",\"message\":" + jsonString(attempt.message.toString()) +
                   ",\"trace\":" + jsonString(messageText(attempt.message));
            if (!attempt.output.empty()) {
                out += ",\"stdout\":" + lines(attempt.output);
            }
            out += ",\"extra\":{" + std::string(extension) +
                   ":{\"state\":" + jsonString(toString(attempt.status)) + "}}}";
        }
        out += "]";
    }
    const std::string attachments = attachmentsOf(events);
    if (!attachments.empty()) {
        out += ",\"attachments\":[" + attachments + "]";
    }
    out += std::string(",\"flaky\":") + (test.status == TestStatus::Flaky ? "true" : "false");
    out += ",\"extra\":{" + std::string(extension) +
           ":{\"state\":" + jsonString(toString(test.status));
    const std::string fullId = test.key.empty() ? std::string() : suite.name + "/" + test.key;
    if (!fullId.empty()) {
        out += ",\"id\":" + jsonString(fullId);
    }
    out += ",\"name\":" + jsonString(test.name);
    if (!test.description.empty()) {
        out += ",\"description\":" + jsonString(test.description);
    }
    if (test.status == TestStatus::Error || test.status == TestStatus::Crashed) {
        out += ",\"error\":true";
    }
    if (!test.repetitions.empty()) {
        // repetition="N": each repetition by its id, with its state and its first problem.
        out += ",\"repetitions\":[";
        for (std::size_t i = 0; i < test.repetitions.size(); ++i) {
            const TestRepetition& repetition = test.repetitions[i];
            out +=
                std::string(i == 0 ? "" : ",") + "{\"id\":\"" +
                repetitionId(test.id, repetition.index) + "\"" +
                (fullId.empty()
                     ? std::string()
                     : ",\"name\":" + jsonString(fullId + "#" + std::to_string(repetition.index))) +
                ",\"index\":" + std::to_string(repetition.index) +
                ",\"count\":" + std::to_string(repetition.count) +
                ",\"state\":" + jsonString(toString(repetition.status)) +
                ",\"duration\":" + std::to_string(milliseconds(repetition.duration));
            for (const ResultEvent& event : events) {
                if (event.repetition == repetition.index &&
                    stateOf(event.kind) != TestStatus::Passed &&
                    stateOf(event.kind) == repetition.status) {
                    out += ",\"message\":" + jsonString(event.message.toString());
                    break;
                }
            }
            out += "}";
        }
        out += "]";
    }
    if (const ResultEvent* reason = test.reason()) {
        if (test.status == TestStatus::Crashed) {
            out += ",\"crash\":" + jsonString(reason->message.toString());
        } else if (test.status == TestStatus::TimedOut) {
            out += ",\"timeout\":" + jsonString(reason->message.toString());
        }
    }
    const std::string measurements = measurementsOf(events);
    if (!measurements.empty()) {
        out += ",\"measurements\":[" + measurements + "]";
    }
    // Every report and check, whatever -v said, each with its time (ms since the epoch).
    out += ",\"reports\":" + messageList(events, origin, passedChecks, false);
    out += "}}}";
}

}  // namespace

// Written front to back, a test at a time: the runner hands it on to the file as it goes.
void JsonReporter::writeDocument(ReportText& out) {
    const long long origin = std::chrono::duration_cast<std::chrono::milliseconds>(
                                 collector_.startedAt().time_since_epoch())
                                 .count();
    const long long stop = origin + milliseconds(collector_.duration());
    const std::size_t other = collector_.countOf(TestStatus::Interrupted);
    out += "{\"reportFormat\":\"CTRF\",\"specVersion\":\"0.0.0\"";
    out += ",\"timestamp\":\"" + rfc3339(origin) + "\"";
    out += ",\"generatedBy\":\"robottestingframework-testrunner\"";
    out += ",\"results\":{\"tool\":{\"name\":\"robottestingframework-testrunner\"}";
    out += ",\"summary\":{\"tests\":" + std::to_string(collector_.testCount());
    out += ",\"passed\":" +
           std::to_string(collector_.passedCount() + collector_.countOf(TestStatus::Flaky));
    out += ",\"failed\":" + std::to_string(collector_.failedCount() - other);
    out += ",\"skipped\":" + std::to_string(collector_.skippedCount());
    out += ",\"pending\":0,\"other\":" + std::to_string(other);
    out += ",\"suites\":" + std::to_string(collector_.suiteCount());
    out += ",\"start\":" + std::to_string(origin) + ",\"stop\":" + std::to_string(stop);
    out += ",\"duration\":" + std::to_string(stop - origin);
    out += ",\"extra\":{" + std::string(extension) + ":{";
    for (TestStatus status : {TestStatus::Failed, TestStatus::Error, TestStatus::Crashed,
                              TestStatus::TimedOut, TestStatus::Interrupted}) {
        out += (status == TestStatus::Failed ? "" : ",") + jsonString(toString(status)) + ":" +
               std::to_string(collector_.countOf(status));
    }
    out += ",\"flaky\":" + std::to_string(collector_.countOf(TestStatus::Flaky));
    out += ",\"suitesFailed\":" + std::to_string(collector_.failedSuiteCount());
    // The fixtures that failed, counted among the failures by the console's summary and closing
    // line ("failed: 3 (2 tests, 1 fixture)"): one count in every output.
    out += ",\"fixturesFailed\":" + std::to_string(collector_.failedFixtureCount()) + "}}}";
    out += ",\"tests\":[";
    bool first = true;
    std::string fixtures;
    std::string suites;
    std::size_t index = 0;
    for (const SuiteRecord& suite : collector_.suites()) {
        const std::size_t suitePlace = settings_.suitePlace(index++) + 1;
        suites +=
            std::string(suites.empty() ? "" : ",") + "{\"place\":" + std::to_string(suitePlace) +
            ",\"name\":" + jsonString(suite.name) +
            ",\"duration\":" + std::to_string(milliseconds(suite.duration)) +
            ",\"messages\":" + messageList(suite.events, origin, settings_.passedChecks, true);
        // Its fixtures' files (a process fixture's logs), as a test's attachments are.
        const std::string attachments = attachmentsOf(suite.events);
        if (!attachments.empty()) {
            suites += ",\"attachments\":[" + attachments + "]";
        }
        suites += "}";
        std::size_t testPlace = 0;
        for (const TestRecord& test : suite.tests) {
            out += first ? "\n" : ",\n";
            first = false;
            const std::string testId =
                std::to_string(suitePlace) + "." + std::to_string(++testPlace);
            appendTest(out, test, suite, testId, origin, settings_.passedChecks);
        }
        if (suite.fixtureFailed) {
            fixtures += std::string(fixtures.empty() ? "" : ",") +
                        "{\"suite\":" + jsonString(suite.name) +
                        ",\"problems\":" + jsonString(traceText(suite.events));
            if (!suite.output.empty()) {
                fixtures += ",\"stdout\":" + lines(suite.output);
            }
            fixtures += "}";
        }
    }
    out += "]";
    // A fixture that failed is the suite's, not a test's: kept where CTRF leaves room for it.
    out += ",\"extra\":{" + std::string(extension) + ":{\"fixtureFailures\":[" + fixtures + "]";
    // Each suite's time, fixtures included: what --durations balances shards by.
    out += ",\"suites\":[" + suites + "]";
    if (settings_.sharded) {
        out += ",\"shard\":{\"index\":" + std::to_string(settings_.shardIndex) +
               ",\"count\":" + std::to_string(settings_.shardCount) +
               (settings_.shardPlan.empty() ? std::string()
                                            : ",\"plan\":" + jsonString(settings_.shardPlan)) +
               "}";
    }
    if (settings_.rerun) {
        out += ",\"rerun\":true";
    }
    out += "}}";
    out += "}}\n";
}

}  // namespace reporters
}  // namespace robottestingframework
