#include "reporters/junit_reporter.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

#include "core/text_safety.h"
#include "reporters/host_name.h"
#include "reporters/summary.h"

namespace robottestingframework {
namespace reporters {

namespace {

std::string escape(const std::string& text, bool attribute) {
    return escapeMarkup(text, attribute ? Markup::Attribute : Markup::Text);
}

std::string attr(const char* name, const std::string& value) {
    return std::string(" ") + name + "=\"" + escape(value, true) + "\"";
}

std::string number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.3f", value);
    return buffer;
}

std::string timestamp(std::chrono::system_clock::time_point origin, double offset) {
    const auto when = origin + std::chrono::duration_cast<std::chrono::system_clock::duration>(
                                   std::chrono::duration<double>(offset));
    const std::time_t time = std::chrono::system_clock::to_time_t(when);
    std::tm local{};
    localtime_r(&time, &local);
    char buffer[32];
    std::strftime(buffer, sizeof(buffer), "%Y-%m-%dT%H:%M:%S", &local);
    return buffer;
}

// How each state is written, where JUnit has a word for it: the element that marks the test and
// its type= (report_reader.cpp reads the state back from the same pair). A test that timed out
// failed (it did not finish what it checks); a crash, an error or an interruption is an error.
// Flaky has no element: its earlier attempts (<flakyFailure>) and a suite property say it.
struct JUnitProblem {
    const char* element;  // "skipped", "failure", "error"; nullptr when the test passed
    const char* type;
};

JUnitProblem problemOf(TestStatus status) {
    switch (status) {
        case TestStatus::Skipped:
            return {"skipped", nullptr};
        case TestStatus::Failed:
            return {"failure", "failure"};
        case TestStatus::TimedOut:
            return {"failure", "timeout"};
        case TestStatus::Error:
            return {"error", "error"};
        case TestStatus::Crashed:
            return {"error", "crash"};
        case TestStatus::Interrupted:
            return {"error", "interrupted"};
        case TestStatus::Passed:
        case TestStatus::Flaky:
            break;
    }
    return {nullptr, nullptr};
}

bool isErrorState(TestStatus status) {
    const char* element = problemOf(status).element;
    return element != nullptr && std::string(element) == "error";
}

bool isFailureState(TestStatus status) {
    const char* element = problemOf(status).element;
    return element != nullptr && std::string(element) == "failure";
}

// The states JUnit has no word for: a suite property names each test in one of them.
bool needsStateProperty(TestStatus status) {
    return status == TestStatus::TimedOut || status == TestStatus::Crashed ||
           status == TestStatus::Interrupted || status == TestStatus::Flaky;
}

// A crash's message= is the signal's name ("SIGSEGV"), what CI tools show in one line; the
// details keep the whole reason ("crashed: SIGSEGV (Segmentation fault)").
std::string crashSignal(const std::string& reason) {
    const std::size_t at = reason.find("SIG");
    if (at == std::string::npos) {
        return reason;
    }
    std::size_t end = at + 3;
    while (end < reason.size() && ((reason[end] >= 'A' && reason[end] <= 'Z') ||
                                   (reason[end] >= '0' && reason[end] <= '9'))) {
        ++end;
    }
    return end > at + 3 ? reason.substr(at, end - at) : reason;
}

bool isProblem(ResultEvent::Kind kind) {
    return isFailure(stateOf(kind));
}

// Every failure and error of `events`, one per line, with where it happened.
std::string problems(const std::vector<ResultEvent>& events) {
    std::string text;
    for (const ResultEvent& event : events) {
        if (isProblem(event.kind)) {
            text += eventLabel(event.kind, event.passed) + ": " + messageText(event.message) + "\n";
        }
    }
    return text;
}

// A measurement as Jenkins reads one from <system-out> (each on its own line): the words,
// then "[[PROPERTY|name=value]]". junit-10.xsd allows no <properties> in a <testcase>.
// Jenkins knows no escape there: in the name, what would end it or the line early (`=`, `[`,
// `]`, `|`, a control character) is `_`; the words above keep the name as it was given.
std::string measurementLines(const Measurement& measurement) {
    std::string name = measurement.name;  // one line, whatever the test called it
    std::replace_if(
        name.begin(), name.end(),
        [](char ch) {
            const auto c = static_cast<unsigned char>(ch);
            return c < 0x20 || c == 0x7F || ch == '=' || ch == '[' || ch == ']' || ch == '|';
        },
        '_');
    return "measurement: " + visibleText(describeMeasurement(measurement)) + "\n[[PROPERTY|" +
           name + "=" + formatNumber(measurement.value) + "]]\n";
}

// An attachment as Jenkins' junit-attachments plug-in reads one: "[[ATTACHMENT|path]]" alone
// on its line, the path absolute.
std::string attachmentLines(const Attachment& attachment) {
    return "attachment: " + visibleText(describeAttachment(attachment)) + "\n[[ATTACHMENT|" +
           attachment.absolutePath + "]]\n";
}

std::string systemOut(const std::vector<ResultEvent>& events, const std::string& output,
                      bool passedChecks) {
    std::string text;
    for (const ResultEvent& event : events) {
        if (isMessage(event.kind) && (!isCheck(event.kind) || passedChecks)) {
            text += eventLabel(event.kind, event.passed) + ": " + messageText(event.message) + "\n";
        } else if (isMeasurement(event)) {
            text += measurementLines(*event.measurement);
        } else if (isAttachment(event)) {
            text += attachmentLines(*event.attachment);
        }
    }
    return text + output;
}

struct Counts {
    std::size_t tests = 0;
    std::size_t failures = 0;
    std::size_t errors = 0;
    std::size_t skipped = 0;
};

// The numbers of a suite's <testsuite> element, as readers recount them from the elements: a
// failed fixture is a <testcase> of its own ("fixtures"), counted in tests= and errors=.
Counts countsOf(const SuiteRecord& suite) {
    Counts counts;
    counts.tests = suite.tests.size();
    for (const TestRecord& test : suite.tests) {
        if (test.status == TestStatus::Skipped) {
            ++counts.skipped;
        } else if (isErrorState(test.status)) {
            ++counts.errors;
        } else if (isFailureState(test.status)) {
            ++counts.failures;
        }
    }
    if (suite.fixtureFailed) {
        ++counts.tests;
        ++counts.errors;
    }
    return counts;
}

// An earlier failed attempt (--retries), as Maven Surefire writes it: message= and type= on the
// element, the details in <stackTrace>, then what it printed in <system-out>.
void appendAttempt(std::string& inner, const char* element, const TestAttempt& attempt) {
    inner += std::string("      <") + element + attr("message", attempt.message.toString()) +
             attr("type", toString(attempt.status)) + ">\n        <stackTrace>" +
             escape(messageText(attempt.message), false) + "</stackTrace>\n";
    if (!attempt.output.empty()) {
        inner += "        <system-out>" + escape(attempt.output, false) + "</system-out>\n";
    }
    inner += std::string("      </") + element + ">\n";
}

void appendTestCase(ReportText& out, const TestRecord& test, const std::string& suiteName,
                    bool passedChecks) {
    // Its measurements among its events, as events: what this format lists.
    std::vector<ResultEvent> scratch;
    const std::vector<ResultEvent>& events = test.eventsInOrder(scratch);
    out += "    <testcase";
    // classname/name is the test's id (docs/reference/test-ids.md), so CI history follows a test
    // across workspaces; the name it gave itself is a property of the suite ("rtf.name.S.T":
    // junit-10.xsd allows no <properties> in a <testcase>).
    out += attr("name", test.reportName());
    out += attr("classname", suiteName);
    out += attr("time", number(test.duration));
    std::string inner;
    const ResultEvent* reason = test.reason();
    const std::string message = reason ? reason->message.toString() : "";
    const JUnitProblem problem = problemOf(test.status);
    if (test.status == TestStatus::Skipped) {
        inner += "      <skipped" + attr("message", message) + ">" + escape(message, false) +
                 "</skipped>\n";
    } else if (problem.element != nullptr) {
        const std::string summary =
            test.status == TestStatus::Crashed ? crashSignal(message) : message;
        inner += std::string("      <") + problem.element + attr("message", summary) +
                 attr("type", problem.type) + ">" + escape(problems(events), false) + "</" +
                 problem.element + ">\n";
    }
    // Earlier failed attempts follow the final one, as Surefire orders them: <flakyFailure> when
    // the last attempt passed, else <rerunFailure> after a <failure> and <rerunError> after an
    // <error>. Each one's type= is its own state.
    if (test.status == TestStatus::Flaky || problem.type != nullptr) {
        const char* element = test.status == TestStatus::Flaky ? "flakyFailure"
                              : isErrorState(test.status)      ? "rerunError"
                                                               : "rerunFailure";
        for (const TestAttempt& attempt : test.attempts) {
            appendAttempt(inner, element, attempt);
        }
    }
    const std::string output = systemOut(events, test.output, passedChecks);
    if (!output.empty()) {
        inner += "      <system-out>" + escape(output, false) + "</system-out>\n";
    }
    if (inner.empty()) {
        out += "/>\n";
    } else {
        out += ">\n";
        out += inner;
        out += "    </testcase>\n";
    }
}

// A suite's <properties>. The shard that wrote the report and a --rerun-failed run, on the
// first suite only (<testsuites> may hold no properties in the readers' schemas, and
// xunitparser refuses a property name twice in a document); then, per test (S.T its place, as
// CTRF's testId): "rtf.name.S.T" = the name it gave itself (beside its id, the testcase's
// name=), and "rtf.state.S.T" = its state when JUnit has no word for it.
std::string suiteProperties(const ReporterSettings& settings, bool first, const SuiteRecord* suite,
                            std::size_t place) {
    std::string text;
    auto property = [&text](const std::string& name, const std::string& value) {
        text += "      <property" + attr("name", name) + attr("value", value) + "/>\n";
    };
    if (first && settings.sharded) {
        property("rtf.shard.index", std::to_string(settings.shardIndex));
        property("rtf.shard.count", std::to_string(settings.shardCount));
        if (!settings.shardPlan.empty()) {
            property("rtf.shard.plan", settings.shardPlan);
        }
    }
    if (first && settings.rerun) {
        property("rtf.rerun", "true");
    }
    if (suite != nullptr) {
        std::size_t index = 0;
        for (const TestRecord& test : suite->tests) {
            ++index;
            const std::string at = std::to_string(place) + "." + std::to_string(index);
            if (!test.key.empty()) {
                property("rtf.name." + at, test.name);
            }
            if (needsStateProperty(test.status)) {
                property("rtf.state." + at, toString(test.status));
            }
        }
    }
    return text.empty() ? text : "    <properties>\n" + text + "    </properties>\n";
}

}  // namespace

// Written front to back (the counts are known before the elements they head), a test at a time:
// the runner hands it on to the file as it goes.
void JUnitReporter::writeDocument(ReportText& out) {
    const bool passedChecks = settings_.passedChecks;
    const std::string host = hostName();
    Counts total;
    double totalTime = 0;
    for (const SuiteRecord& suite : collector_.suites()) {
        const Counts counts = countsOf(suite);
        total.tests += counts.tests;
        total.failures += counts.failures;
        total.errors += counts.errors;
        totalTime += suite.duration;
    }
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites";
    out += attr("name", "RobotTestingFramework");
    out += attr("tests", std::to_string(total.tests));
    out += attr("failures", std::to_string(total.failures));
    out += attr("errors", std::to_string(total.errors));
    out += attr("time", number(collector_.duration() > 0 ? collector_.duration() : totalTime));
    out += ">\n";
    if (collector_.suites().empty() && (settings_.sharded || settings_.rerun)) {
        // A shard with no suite still says which it is (--merge --expect-shards): in a suite
        // with no tests and no id, which is no suite of the run (report_reader.cpp).
        out += "  <testsuite" + attr("name", "RobotTestingFramework") +
               " tests=\"0\" failures=\"0\" errors=\"0\" skipped=\"0\" time=\"0.000\">\n" +
               suiteProperties(settings_, true, nullptr, 0) + "  </testsuite>\n";
    }
    std::size_t index = 0;
    for (const SuiteRecord& suite : collector_.suites()) {
        const std::string suiteName = suite.name.empty() ? "default" : suite.name;
        const Counts counts = countsOf(suite);
        out += "  <testsuite";
        out += attr("name", suiteName);
        out += attr("tests", std::to_string(counts.tests));
        out += attr("failures", std::to_string(counts.failures));
        out += attr("errors", std::to_string(counts.errors));
        out += attr("skipped", std::to_string(counts.skipped));
        out += attr("time", number(suite.duration));
        out += attr("timestamp", timestamp(collector_.startedAt(), suite.start));
        out += attr("hostname", host);
        const std::size_t place = settings_.suitePlace(index);
        out += attr("id", std::to_string(place));
        out += ">\n";
        out += suiteProperties(settings_, index++ == 0, &suite, place + 1);
        for (const TestRecord& test : suite.tests) {
            appendTestCase(out, test, suiteName, passedChecks);
        }
        // A fixture that failed or collapsed is an error of its own, so CI shows the suite red
        // even when every test was only skipped.
        const std::string suiteProblems = problems(suite.events);
        if (suite.fixtureFailed) {
            std::string first;
            for (const ResultEvent& event : suite.events) {
                if (isProblem(event.kind)) {
                    first = event.message.toString();
                    break;
                }
            }
            out += "    <testcase" + attr("name", "fixtures") + attr("classname", suiteName) +
                   attr("time", "0.000") + ">\n      <error" + attr("message", first) +
                   attr("type", "fixture") + ">" + escape(suiteProblems, false) +
                   "</error>\n    </testcase>\n";
        }
        const std::string output = systemOut(suite.events, suite.output, passedChecks);
        if (!output.empty()) {
            out += "    <system-out>" + escape(output, false) + "</system-out>\n";
        }
        if (!suiteProblems.empty()) {
            out += "    <system-err>" + escape(suiteProblems, false) + "</system-err>\n";
        }
        out += "  </testsuite>\n";
    }
    out += "</testsuites>\n";
}

}  // namespace reporters
}  // namespace robottestingframework
