#include "runner/reports/imported_report.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

#include "platform/bounded_file.h"

namespace robottestingframework {
namespace runner {

namespace {

const char* const option = "--history-import";

// Days from 1970-01-01 to the given day of the proleptic Gregorian calendar (month 1 to 12):
// timegm's arithmetic, which Windows lacks.
long long daysFromCivil(long long year, unsigned month, unsigned day) {
    year -= month <= 2 ? 1 : 0;
    const long long era = (year >= 0 ? year : year - 399) / 400;
    const unsigned yearOfEra = static_cast<unsigned>(year - era * 400);
    const unsigned dayOfYear = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
    const unsigned dayOfEra = yearOfEra * 365 + yearOfEra / 4 - yearOfEra / 100 + dayOfYear;
    return era * 146097 + static_cast<long long>(dayOfEra) - 719468;
}

// "2024-05-01T10:20:30" (JUnit's timestamp, UTC), or -1. std::get_time rather than strptime
// and timegm, which Windows lacks.
double isoSeconds(const std::string& text) {
    std::tm when{};
    std::istringstream in(text);
    in >> std::get_time(&when, "%Y-%m-%dT%H:%M:%S");
    if (in.fail()) {
        return -1;
    }
    const long long days =
        daysFromCivil(when.tm_year + 1900LL, when.tm_mon + 1u, static_cast<unsigned>(when.tm_mday));
    return static_cast<double>(days * 86400 + when.tm_hour * 3600 + when.tm_min * 60 + when.tm_sec);
}

double secondsOf(const char* text) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    return end != text && value > 0 ? value : 0;
}

void addSuiteTime(ImportedReport& report, const std::string& suite, double seconds) {
    for (ReportedSuite& known : report.suites) {
        if (known.name == suite) {
            known.seconds += seconds;
            return;
        }
    }
    report.suites.push_back({suite, seconds});
}

void readForeignJUnit(ImportedReport& report, const std::string& text, const std::string& path) {
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_string(text.c_str());
    if (!parsed) {
        throw std::runtime_error(std::string(option) + " " + path + ": not valid XML (" +
                                 parsed.description() + ")");
    }
    const pugi::xml_node root = document.document_element();
    std::vector<pugi::xml_node> suites;
    if (std::string(root.name()) == "testsuite") {
        suites.push_back(root);
    } else if (std::string(root.name()) == "testsuites") {
        for (const pugi::xpath_node suite : root.select_nodes("//testsuite")) {
            suites.push_back(suite.node());  // nested suites too (some tools nest them)
        }
        report.started = isoSeconds(root.attribute("timestamp").value());
    } else {
        throw std::runtime_error(std::string(option) + " " + path + ": not a JUnit report " +
                                 "(expected <testsuites> or <testsuite>, found <" + root.name() +
                                 ">)");
    }
    for (const pugi::xml_node suite : suites) {
        const std::string suiteName = suite.attribute("name").value();
        if (report.started < 0) {
            report.started = isoSeconds(suite.attribute("timestamp").value());
        }
        for (const pugi::xml_node test : suite.children("testcase")) {
            ReportedTest reported;
            reported.suite = suiteName;
            reported.name = test.attribute("name").value();
            if (reported.name.empty()) {
                reported.name = test.attribute("classname").value();
            }
            reported.seconds = secondsOf(test.attribute("time").value());
            reported.state = test.child("skipped")                                      ? "skipped"
                             : test.child("failure")                                    ? "failed"
                             : test.child("error")                                      ? "error"
                             : (test.child("flakyFailure") || test.child("flakyError")) ? "flaky"
                                                                                        : "passed";
            for (const pugi::xml_node attempt : test.children()) {
                const std::string element = attempt.name();
                if (element.rfind("flaky", 0) == 0 || element.rfind("rerun", 0) == 0) {
                    ++reported.attempts;
                }
            }
            addSuiteTime(report, suiteName, reported.seconds);
            report.tests.push_back(reported);
        }
    }
}

void readForeignCtrf(ImportedReport& report, const std::string& text, const std::string& path) {
    const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
    if (!document.is_object() || !document.contains("results") ||
        !document["results"].is_object() || !document["results"].contains("tests") ||
        !document["results"]["tests"].is_array()) {
        throw std::runtime_error(std::string(option) + " " + path +
                                 ": not a CTRF report (expected results.tests)");
    }
    const auto& results = document["results"];
    const auto start = results.value("/summary/start"_json_pointer, nlohmann::json());
    if (start.is_number() && start.get<double>() > 0) {
        report.started = start.get<double>() / 1000.0;
    }
    std::size_t index = 0;
    for (const auto& test : results["tests"]) {
        const std::string where =
            std::string(option) + " " + path + ": results.tests[" + std::to_string(index++) + "]";
        if (!test.is_object() || !test.contains("name") || !test["name"].is_string() ||
            !test.contains("status") || !test["status"].is_string()) {
            throw std::runtime_error(where + ": expected a test with a name and a status");
        }
        ReportedTest reported;
        reported.name = test["name"].get<std::string>();
        if (test.contains("suite")) {
            if (test["suite"].is_string()) {
                reported.suite = test["suite"].get<std::string>();
            } else if (test["suite"].is_array()) {
                for (const auto& part : test["suite"]) {
                    if (part.is_string()) {
                        reported.suite +=
                            (reported.suite.empty() ? "" : "/") + part.get<std::string>();
                    }
                }
            }
        }
        if (test.contains("duration") && test["duration"].is_number()) {
            reported.seconds = std::max(0.0, test["duration"].get<double>() / 1000.0);
        }
        if (test.contains("retries") && test["retries"].is_number_unsigned()) {
            reported.attempts += test["retries"].get<unsigned int>();
        }
        const std::string status = test["status"].get<std::string>();
        const bool flaky = test.value("flaky", false) && status == "passed";
        reported.state = flaky                                        ? "flaky"
                         : status == "passed"                         ? "passed"
                         : status == "failed"                         ? "failed"
                         : status == "skipped" || status == "pending" ? "skipped"
                                                                      : "error";
        addSuiteTime(report, reported.suite, reported.seconds);
        report.tests.push_back(reported);
    }
}

// FNV-1a over 64 bits, in hex: enough to know a report imported before (not a defence against
// a report made to collide).
std::string digestOf(const std::string& text) {
    std::uint64_t hash = 14695981039346656037ULL;
    for (const char c : text) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 1099511628211ULL;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

}  // namespace

ImportedReport readImportedReport(const std::string& path) {
    std::string text;
    std::string error;
    if (!platform::readBoundedFile(path, "report", maxReportBytes, platform::Pipes::Read, text,
                                   error)) {
        throw std::runtime_error(std::string(option) + " " + error);
    }
    ImportedReport imported;
    imported.digest = digestOf(text);
    try {
        Report report = parseReport(option, text, path);
        imported.ours = true;
        imported.tests = std::move(report.tests);
        imported.suites = std::move(report.suites);
        if (report.format == ReportFormat::Json) {
            const auto start =
                report.json.value("/results/summary/start"_json_pointer, nlohmann::ordered_json());
            if (start.is_number()) {
                imported.started = start.get<double>() / 1000.0;
            }
        } else {
            const pugi::xml_node root = report.junit->document_element();
            imported.started = isoSeconds(root.attribute("timestamp").value());
            if (imported.started < 0) {
                imported.started =
                    isoSeconds(root.child("testsuite").attribute("timestamp").value());
            }
        }
        return imported;
    } catch (const std::runtime_error&) {
        // Not this runner's: read it as any tool's.
    }
    const std::size_t first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (first != std::string::npos && text[first] == '<') {
        readForeignJUnit(imported, text, path);
    } else if (first != std::string::npos && text[first] == '{') {
        readForeignCtrf(imported, text, path);
    } else {
        throw std::runtime_error(std::string(option) + " " + path +
                                 ": neither a JUnit (XML) nor a CTRF (JSON) report");
    }
    return imported;
}

}  // namespace runner
}  // namespace robottestingframework
