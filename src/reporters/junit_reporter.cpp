#include "reporters/junit_reporter.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>

#include "reporters/summary.h"
#include "reporters/text_safety.h"

namespace robottestingframework {
namespace reporters {

namespace {

using Kind = ResultEvent::Kind;

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

std::string hostname() {
    char buffer[256] = {};
    if (gethostname(buffer, sizeof(buffer) - 1) != 0) {
        return "localhost";
    }
    return buffer;
}

bool isErrorState(TestStatus status) {
    return status == TestStatus::Error || status == TestStatus::Crashed ||
           status == TestStatus::TimedOut || status == TestStatus::Interrupted;
}

const char* errorType(TestStatus status) {
    switch (status) {
        case TestStatus::Crashed:
            return "crash";
        case TestStatus::TimedOut:
            return "timeout";
        case TestStatus::Interrupted:
            return "interrupted";
        default:
            return "error";
    }
}

bool isProblem(Kind kind) {
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

std::string systemOut(const std::vector<ResultEvent>& events, const std::string& output,
                      bool verbose) {
    std::string text;
    for (const ResultEvent& event : events) {
        if (event.kind == Kind::Report || (verbose && event.kind == Kind::Check)) {
            text += eventLabel(event.kind, event.passed) + ": " + messageText(event.message) + "\n";
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

// The numbers of a suite's <testsuite> element; a failed fixture counts as one error more,
// but not as a test (tests= counts the suite's tests, which carry the fixture's reason).
Counts countsOf(const SuiteRecord& suite) {
    Counts counts;
    counts.tests = suite.tests.size();
    for (const TestRecord& test : suite.tests) {
        if (test.status == TestStatus::Skipped) {
            ++counts.skipped;
        } else if (isErrorState(test.status)) {
            ++counts.errors;
        } else if (test.status == TestStatus::Failed) {
            ++counts.failures;
        }
    }
    if (suite.fixtureFailed) {
        ++counts.errors;
    }
    return counts;
}

void appendTestCase(std::string& out, const TestRecord& test, const std::string& suiteName,
                    bool verbose) {
    out += "    <testcase";
    // classname/name is the test's id (README: "Test ids"), so CI history follows a test
    // across workspaces; the name it gave itself is a property beside.
    out += attr("name", test.reportName());
    out += attr("classname", suiteName);
    out += attr("time", number(test.duration));
    out += attr("status", toString(test.status));
    std::string inner;
    if (!test.key.empty()) {
        inner += "      <properties>\n        <property" + attr("name", "rtf.name") +
                 attr("value", test.name) + "/>\n      </properties>\n";
    }
    const ResultEvent* reason = test.reason();
    const std::string message = reason ? reason->message.toString() : "";
    if (test.status == TestStatus::Skipped) {
        inner += "      <skipped>" + escape(message, false) + "</skipped>\n";
    } else if (isErrorState(test.status)) {
        inner += "      <error" + attr("message", message) + attr("type", errorType(test.status)) +
                 ">" + escape(problems(test.events), false) + "</error>\n";
    } else if (test.status == TestStatus::Failed) {
        inner += "      <failure" + attr("message", message) + attr("type", "failure") + ">" +
                 escape(problems(test.events), false) + "</failure>\n";
    }
    // Earlier failed attempts (--retries), as Maven Surefire writes them: inside the one
    // <testcase>, flakyFailure when the last attempt passed, rerunFailure when it did not.
    const char* attemptElement = test.status == TestStatus::Flaky ? "flakyFailure" : "rerunFailure";
    if (test.status == TestStatus::Flaky || isErrorState(test.status) ||
        test.status == TestStatus::Failed) {
        for (const TestAttempt& attempt : test.attempts) {
            inner += std::string("      <") + attemptElement +
                     attr("message", attempt.message.toString()) +
                     attr("type", toString(attempt.status)) + ">" +
                     escape(messageText(attempt.message), false);
            if (!attempt.output.empty()) {
                inner += "<system-out>" + escape(attempt.output, false) + "</system-out>";
            }
            inner += std::string("</") + attemptElement + ">\n";
        }
    }
    const std::string output = systemOut(test.events, test.output, verbose);
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

}  // namespace

// Written into one string, front to back (the counts are known before the elements they head):
// a run of 10 000 tests must not hold several copies of its report at once.
std::string JUnitReporter::document() {
    const bool verbose = settings_.verbose;
    const std::string host = hostname();
    Counts total;
    double totalTime = 0;
    std::size_t testCount = 0;
    for (const SuiteRecord& suite : collector_.suites()) {
        const Counts counts = countsOf(suite);
        total.tests += counts.tests;
        total.failures += counts.failures;
        total.errors += counts.errors;
        totalTime += suite.duration;
        testCount += suite.tests.size();
    }
    std::string out;
    out.reserve(512 + testCount * 160);  // a passing test's element is about that long
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites";
    out += attr("name", "RobotTestingFramework");
    out += attr("tests", std::to_string(total.tests));
    out += attr("failures", std::to_string(total.failures));
    out += attr("errors", std::to_string(total.errors));
    out += attr("time", number(collector_.duration() > 0 ? collector_.duration() : totalTime));
    out += ">\n";
    if (settings_.sharded || settings_.rerun) {
        // On the root, so an empty shard says which it is too (--merge --expect-shards).
        out += "  <properties>\n";
        if (settings_.sharded) {
            out += "    <property" + attr("name", "rtf.shard.index") +
                   attr("value", std::to_string(settings_.shardIndex)) + "/>\n    <property" +
                   attr("name", "rtf.shard.count") +
                   attr("value", std::to_string(settings_.shardCount)) + "/>\n";
        }
        if (settings_.rerun) {
            out += "    <property" + attr("name", "rtf.rerun") + attr("value", "true") + "/>\n";
        }
        out += "  </properties>\n";
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
        out += attr("id", std::to_string(settings_.suitePlace(index++)));
        out += ">\n";
        for (const TestRecord& test : suite.tests) {
            appendTestCase(out, test, suiteName, verbose);
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
                   attr("time", "0.000") + attr("status", "error") + ">\n      <error" +
                   attr("message", first) + attr("type", "fixture") + ">" +
                   escape(suiteProblems, false) + "</error>\n    </testcase>\n";
        }
        const std::string output = systemOut(suite.events, suite.output, verbose);
        if (!output.empty()) {
            out += "    <system-out>" + escape(output, false) + "</system-out>\n";
        }
        if (!suiteProblems.empty()) {
            out += "    <system-err>" + escape(suiteProblems, false) + "</system-err>\n";
        }
        out += "  </testsuite>\n";
    }
    out += "</testsuites>\n";
    return out;
}

}  // namespace reporters
}  // namespace robottestingframework
