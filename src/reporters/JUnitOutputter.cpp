#include <robottestingframework/JUnitOutputter.h>

#include <unistd.h>

#include <cstdio>
#include <ctime>

#include "atomic_file.h"
#include "summary.h"

namespace robottestingframework {

namespace {

using Kind = ResultEvent::Kind;

// Length of the valid UTF-8 sequence at s[i] that XML 1.0 allows, 0 when there is none.
std::size_t validSequence(const std::string& s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    unsigned char low = 0x80;
    unsigned char high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        if (lead == 0xE0) {
            low = 0xA0;  // overlong
        } else if (lead == 0xED) {
            high = 0x9F;  // surrogates
        }
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        if (lead == 0xF0) {
            low = 0x90;
        } else if (lead == 0xF4) {
            high = 0x8F;
        }
    } else {
        return 0;
    }
    if (i + length > s.size() || byte(i + 1) < low || byte(i + 1) > high) {
        return 0;
    }
    for (std::size_t k = 2; k < length; ++k) {
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) {
            return 0;
        }
    }
    // U+FFFE and U+FFFF are not XML characters.
    if (length == 3 && lead == 0xEF && byte(i + 1) == 0xBF && byte(i + 2) >= 0xBE) {
        return 0;
    }
    return length;
}

// Escapes for XML and drops what XML cannot hold: control characters other than tab, newline
// and carriage return, and bytes that are not valid UTF-8.
std::string escape(const std::string& text, bool attribute) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x80) {
            const std::size_t length = validSequence(text, i);
            if (length == 0) {
                ++i;
            } else {
                out.append(text, i, length);
                i += length;
            }
            continue;
        }
        ++i;
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += attribute ? "&quot;" : "\"";
                break;
            case '\r':
                out += "&#13;";
                break;
            case '\n':
                out += attribute ? "&#10;" : "\n";
                break;
            case '\t':
                out += attribute ? "&#9;" : "\t";
                break;
            default:
                if (c >= 0x20) {
                    out += static_cast<char>(c);
                }
        }
    }
    return out;
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
    return kind == Kind::Failure || kind == Kind::Error || kind == Kind::Crash ||
           kind == Kind::Timeout || kind == Kind::Interrupted;
}

// Every failure and error of `events`, one per line, with where it happened.
std::string problems(const std::vector<ResultEvent>& events) {
    std::string text;
    for (const ResultEvent& event : events) {
        if (isProblem(event.kind)) {
            text += reporters::eventLabel(event.kind, event.passed) + ": " +
                    reporters::messageText(event.message) + "\n";
        }
    }
    return text;
}

std::string systemOut(const std::vector<ResultEvent>& events, const std::string& output,
                      bool verbose) {
    std::string text;
    for (const ResultEvent& event : events) {
        if (event.kind == Kind::Report || (verbose && event.kind == Kind::Check)) {
            text += reporters::eventLabel(event.kind, event.passed) + ": " +
                    reporters::messageText(event.message) + "\n";
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

}  // namespace

JUnitOutputter::JUnitOutputter(TestResultCollector& collector, bool verbose)
    : collector_(collector), verbose_(verbose) {}

std::string JUnitOutputter::xml() const {
    const std::string host = hostname();
    std::string body;
    Counts total;
    double totalTime = 0;
    std::size_t id = 0;
    for (const SuiteRecord& suite : collector_.suites()) {
        const std::string suiteName = suite.name.empty() ? "default" : suite.name;
        Counts counts;
        std::string cases;
        for (const TestRecord& test : suite.tests) {
            ++counts.tests;
            cases += "    <testcase" + attr("name", test.name) + attr("classname", suiteName) +
                     attr("time", number(test.duration)) + attr("status", toString(test.status));
            std::string inner;
            const ResultEvent* reason = test.reason();
            const std::string message = reason ? reason->message.toString() : "";
            if (test.status == TestStatus::Skipped) {
                ++counts.skipped;
                inner += "      <skipped>" + escape(message, false) + "</skipped>\n";
            } else if (isErrorState(test.status)) {
                ++counts.errors;
                inner += "      <error" + attr("message", message) +
                         attr("type", errorType(test.status)) + ">" +
                         escape(problems(test.events), false) + "</error>\n";
            } else if (test.status == TestStatus::Failed) {
                ++counts.failures;
                inner += "      <failure" + attr("message", message) + attr("type", "failure") +
                         ">" + escape(problems(test.events), false) + "</failure>\n";
            }
            const std::string out = systemOut(test.events, test.output, verbose_);
            if (!out.empty()) {
                inner += "      <system-out>" + escape(out, false) + "</system-out>\n";
            }
            cases += inner.empty() ? "/>\n" : ">\n" + inner + "    </testcase>\n";
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
            ++counts.tests;
            ++counts.errors;
            cases += "    <testcase" + attr("name", "fixtures") + attr("classname", suiteName) +
                     attr("time", "0.000") + attr("status", "error") + ">\n      <error" +
                     attr("message", first) + attr("type", "fixture") + ">" +
                     escape(suiteProblems, false) + "</error>\n    </testcase>\n";
        }
        body +=
            "  <testsuite" + attr("name", suiteName) + attr("tests", std::to_string(counts.tests)) +
            attr("failures", std::to_string(counts.failures)) +
            attr("errors", std::to_string(counts.errors)) +
            attr("skipped", std::to_string(counts.skipped)) + attr("time", number(suite.duration)) +
            attr("timestamp", timestamp(collector_.startedAt(), suite.start)) +
            attr("hostname", host) + attr("id", std::to_string(id++)) + ">\n" + cases;
        const std::string out = systemOut(suite.events, suite.output, verbose_);
        if (!out.empty()) {
            body += "    <system-out>" + escape(out, false) + "</system-out>\n";
        }
        if (!suiteProblems.empty()) {
            body += "    <system-err>" + escape(suiteProblems, false) + "</system-err>\n";
        }
        body += "  </testsuite>\n";
        total.tests += counts.tests;
        total.failures += counts.failures;
        total.errors += counts.errors;
        totalTime += suite.duration;
    }
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites" +
           attr("name", "RobotTestingFramework") + attr("tests", std::to_string(total.tests)) +
           attr("failures", std::to_string(total.failures)) +
           attr("errors", std::to_string(total.errors)) +
           attr("time", number(collector_.duration() > 0 ? collector_.duration() : totalTime)) +
           ">\n" + body + "</testsuites>\n";
}

bool JUnitOutputter::write(std::string filename, TestMessage* error) {
    std::string why;
    if (reporters::writeFileAtomically(filename, xml(), why)) {
        return true;
    }
    if (error != nullptr) {
        error->setMessage(why);
    } else {
        std::fprintf(stderr, "robottestingframework: %s\n", why.c_str());
    }
    return false;
}

}  // namespace robottestingframework
