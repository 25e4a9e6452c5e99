#include "runner/reports/report_reader.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "platform/bounded_file.h"

namespace robottestingframework {
namespace runner {

const char* const shardIndexProperty = "rtf.shard.index";
const char* const shardCountProperty = "rtf.shard.count";
const char* const shardPlanProperty = "rtf.shard.plan";
const char* const rerunProperty = "rtf.rerun";
const char* const ctrfExtensionKey = "robotology.rtf";

bool isJUnitFixtureCase(const pugi::xml_node test) {
    return std::string(test.child("error").attribute("type").value()) == "fixture";
}

namespace {

const char* const runnerName = "robottestingframework-testrunner";

// The states a report of this runner may give a test (TestStatus's words).
bool knownState(const std::string& state) {
    static const char* const states[] = {"passed",  "failed",    "skipped", "error",
                                         "crashed", "timed out", "flaky",   "interrupted"};
    return std::any_of(std::begin(states), std::end(states),
                       [&](const char* known) { return state == known; });
}

// CTRF's test statuses.
bool ctrfStatus(const std::string& status) {
    static const char* const statuses[] = {"passed", "failed", "skipped", "pending", "other"};
    return std::any_of(std::begin(statuses), std::end(statuses),
                       [&](const char* known) { return status == known; });
}

// Reads what a problem needs to name where it is.
class Place {
public:
    Place(std::string option, std::string path, const std::string& text)
        : option_(std::move(option)), path_(std::move(path)), text_(text) {}

    std::runtime_error error(long offset, const std::string& what) const {
        std::string where = path_;
        if (offset >= 0) {
            const auto end = text_.begin() + std::min<long>(offset, text_.size());
            where += ":" + std::to_string(1 + std::count(text_.begin(), end, '\n'));
        }
        return std::runtime_error(option_ + " " + where + ": " + what);
    }

private:
    std::string option_;
    std::string path_;
    const std::string& text_;
};

bool parseSeconds(const char* text, double& value) {
    char* end = nullptr;
    value = std::strtod(text, &end);
    return *text != '\0' && *end == '\0' && value >= 0;
}

bool parseWhole(const std::string& text, unsigned int& value) {
    if (text.empty() || text.size() > 9 ||
        text.find_first_not_of("0123456789") != std::string::npos) {
        return false;
    }
    value = static_cast<unsigned int>(std::strtoul(text.c_str(), nullptr, 10));
    return true;
}

// "3.12": a test's suite place and its place in the suite.
bool isTestId(const std::string& id) {
    unsigned int suite = 0;
    unsigned int test = 0;
    const std::size_t dot = id.find('.');
    return dot != std::string::npos && parseWhole(id.substr(0, dot), suite) &&
           parseWhole(id.substr(dot + 1), test);
}

void checkShard(const ReportedShard& shard, const Place& place, long offset) {
    if (shard.known && (shard.count == 0 || shard.index >= shard.count)) {
        throw place.error(offset, "shard " + std::to_string(shard.index) + " of " +
                                      std::to_string(shard.count) +
                                      ": expected an index below a count of at least 1");
    }
}

// A report's shard properties: on each <testsuite> (an empty shard's in a suite with no id), or
// on <testsuites> in the reports of earlier versions.
void readJUnitShard(Report& report, const pugi::xml_node root, const Place& place) {
    std::vector<pugi::xml_node> holders{root};
    for (const pugi::xml_node suite : root.children("testsuite")) {
        holders.push_back(suite);
    }
    bool haveIndex = false;
    bool haveCount = false;
    long where = -1;
    for (const pugi::xml_node holder : holders) {
        const pugi::xml_node properties = holder.child("properties");
        bool holderIndex = false;
        bool holderCount = false;
        for (const pugi::xml_node property : properties.children("property")) {
            const std::string name = property.attribute("name").value();
            const std::string value = property.attribute("value").value();
            unsigned int* target = name == shardIndexProperty   ? &report.shard.index
                                   : name == shardCountProperty ? &report.shard.count
                                                                : nullptr;
            if (target != nullptr && !parseWhole(value, *target)) {
                throw place.error(property.offset_debug(),
                                  "property " + name + " '" + value + "': expected a whole number");
            }
            holderIndex = holderIndex || name == shardIndexProperty;
            holderCount = holderCount || name == shardCountProperty;
            if (name == shardPlanProperty && report.shard.plan.empty()) {
                report.shard.plan = value;
            }
            if (name == rerunProperty) {
                report.shard.rerun = report.shard.rerun || value == "true";
            }
        }
        if (holderIndex != holderCount) {
            throw place.error(properties.offset_debug(), std::string("expected both properties ") +
                                                             shardIndexProperty + " and " +
                                                             shardCountProperty);
        }
        if (holderIndex && where < 0) {
            where = properties.offset_debug();
        }
        haveIndex = haveIndex || holderIndex;
        haveCount = haveCount || holderCount;
    }
    report.shard.known = haveIndex && haveCount;
    checkShard(report.shard, place, where);
}

}  // namespace

// The reverse of junit_reporter.cpp's table (problemOf): the element that marks a test and its
// type= give its state; earlier attempts after a pass (<flakyFailure>) make it flaky.
std::string junitTestState(const pugi::xml_node test) {
    if (const pugi::xml_attribute status = test.attribute("status")) {
        return status.value();  // the reports of earlier versions say it
    }
    if (test.child("skipped")) {
        return "skipped";
    }
    if (const pugi::xml_node failure = test.child("failure")) {
        return std::string(failure.attribute("type").value()) == "timeout" ? "timed out" : "failed";
    }
    if (const pugi::xml_node error = test.child("error")) {
        const std::string type = error.attribute("type").value();
        return type == "crash" ? "crashed" : type == "interrupted" ? "interrupted" : "error";
    }
    if (test.child("flakyFailure") || test.child("flakyError")) {
        return "flaky";
    }
    return "passed";
}

bool isJUnitRunSuite(const pugi::xml_node suite) {
    return suite.attribute("id") || suite.child("testcase");
}

namespace {

void readJUnit(Report& report, const std::string& text, const Place& place) {
    report.junit = std::make_shared<pugi::xml_document>();
    const pugi::xml_parse_result parsed = report.junit->load_string(text.c_str());
    if (!parsed) {
        throw place.error(parsed.offset,
                          std::string("not valid XML (") + parsed.description() + ")");
    }
    const pugi::xml_node root = report.junit->document_element();
    if (std::string(root.name()) != "testsuites" ||
        std::string(root.attribute("name").value()) != "RobotTestingFramework") {
        throw place.error(root.offset_debug(),
                          "not a JUnit output of this runner (expected <testsuites "
                          "name=\"RobotTestingFramework\">)");
    }
    readJUnitShard(report, root, place);
    for (const pugi::xml_node suite : root.children()) {
        if (std::string(suite.name()) == "properties") {
            continue;
        }
        if (std::string(suite.name()) != "testsuite") {
            throw place.error(suite.offset_debug(), std::string("unexpected <") + suite.name() +
                                                        "> (expected <testsuite>)");
        }
        if (!isJUnitRunSuite(suite)) {
            continue;  // an empty shard's properties
        }
        const std::string suiteName = suite.attribute("name").value();
        ReportedSuite reported{suiteName, 0};
        unsigned int id = 0;
        if (suiteName.empty() || !parseSeconds(suite.attribute("time").value(), reported.seconds) ||
            !parseWhole(suite.attribute("id").value(), id)) {
            throw place.error(suite.offset_debug(),
                              "expected <testsuite> with a name, a time in seconds and an id "
                              "(its place in the run)");
        }
        report.suites.push_back(reported);
        for (const pugi::xml_node test : suite.children("testcase")) {
            const std::string state = junitTestState(test);
            if (test.attribute("name").value()[0] == '\0' || !knownState(state)) {
                throw place.error(test.offset_debug(),
                                  "expected <testcase> with a name and, when it has one, a "
                                  "status (passed, failed, skipped, error, crashed, timed out, "
                                  "flaky or interrupted)");
            }
            // A failed fixture has a <testcase> of its own: not a test.
            if (isJUnitFixtureCase(test)) {
                continue;
            }
            ReportedTest reportedTest{suiteName == "default" ? "" : suiteName,
                                      test.attribute("name").value(), state};
            parseSeconds(test.attribute("time").value(), reportedTest.seconds);
            for (const pugi::xml_node attempt : test.children()) {
                const std::string element = attempt.name();
                if (element == "flakyFailure" || element == "flakyError" ||
                    element == "rerunFailure" || element == "rerunError") {
                    ++reportedTest.attempts;
                }
            }
            report.tests.push_back(reportedTest);
        }
    }
}

void readJsonShape(Report& report, const Place& place);

void readJson(Report& report, const std::string& text, const Place& place) {
    try {
        report.json = nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw place.error(static_cast<long>(e.byte) - 1,
                          std::string("not valid JSON (") + e.what() + ")");
    } catch (const nlohmann::json::exception& e) {
        // Not a parse_error: a number too large for a double (found by fuzzing).
        throw place.error(-1, std::string("not valid JSON (") + e.what() + ")");
    }
    // The checks below test each value's type before reading it; should one be missed, a bare
    // JSON type error must still name the file.
    try {
        readJsonShape(report, place);
    } catch (const nlohmann::json::exception& e) {
        throw place.error(
            -1, std::string("not a JSON (CTRF) output of this runner (") + e.what() + ")");
    }
}

// What --merge reads of the run as a whole, when the report has it: the timestamp and the
// summary's times and counts, and the failed fixtures.
void readJsonRun(const nlohmann::ordered_json& document, const Place& place) {
    for (const char* key : {"specVersion", "timestamp"}) {
        if (document.contains(key) && !document[key].is_string()) {
            throw place.error(-1, std::string(key) + ": expected a string");
        }
    }
    const auto& results = document["results"];
    if (results.contains("summary")) {
        const auto& summary = results["summary"];
        if (!summary.is_object()) {
            throw place.error(-1, "results.summary: expected an object");
        }
        for (const char* key : {"start", "stop"}) {
            if (summary.contains(key) && !summary[key].is_number_integer()) {
                throw place.error(-1, std::string("results.summary.") + key +
                                          ": expected milliseconds since the Unix epoch");
            }
        }
        if (summary.contains("suites") && !summary["suites"].is_number_unsigned()) {
            throw place.error(-1, "results.summary.suites: expected a whole number");
        }
        const auto failed =
            summary.value("/extra/robotology.rtf"_json_pointer, nlohmann::ordered_json());
        if (failed.is_object() && failed.contains("suitesFailed") &&
            !failed["suitesFailed"].is_number_unsigned()) {
            throw place.error(
                -1, "results.summary.extra.robotology.rtf.suitesFailed: expected a whole number");
        }
    }
    const auto extra =
        results.value("/extra/robotology.rtf"_json_pointer, nlohmann::ordered_json::object());
    if (!extra.is_object()) {
        throw place.error(-1, "results.extra.robotology.rtf: expected an object");
    }
    if (extra.contains("fixtureFailures")) {
        const auto& fixtures = extra["fixtureFailures"];
        for (std::size_t i = 0; i < (fixtures.is_array() ? fixtures.size() : 0); ++i) {
            if (!fixtures[i].is_object() ||
                (fixtures[i].contains("suite") && !fixtures[i]["suite"].is_string())) {
                throw place.error(-1, "results.extra.robotology.rtf.fixtureFailures[" +
                                          std::to_string(i) +
                                          "]: expected an object naming its suite");
            }
        }
        if (!fixtures.is_array()) {
            throw place.error(-1,
                              "results.extra.robotology.rtf.fixtureFailures: expected an array");
        }
    }
}

// The key earlier versions gave the runner's CTRF extensions: moved to the namespaced key when
// read, so that what reads them (and --merge, which writes them) knows one key only.
const char* const oldCtrfExtensionKey = "rtf";

void renameOldExtension(nlohmann::ordered_json& object) {
    if (!object.is_object() || !object.contains("extra") || !object["extra"].is_object()) {
        return;
    }
    nlohmann::ordered_json& extra = object["extra"];
    if (extra.contains(oldCtrfExtensionKey) && !extra.contains(ctrfExtensionKey)) {
        extra[ctrfExtensionKey] = std::move(extra[oldCtrfExtensionKey]);
        extra.erase(oldCtrfExtensionKey);
    }
}

void renameOldExtensions(nlohmann::ordered_json& document) {
    nlohmann::ordered_json& results = document["results"];
    renameOldExtension(results);
    if (results.contains("summary")) {
        renameOldExtension(results["summary"]);
    }
    for (nlohmann::ordered_json& test : results["tests"]) {
        renameOldExtension(test);
        if (test.is_object() && test.contains("retryAttempts") &&
            test["retryAttempts"].is_array()) {
            for (nlohmann::ordered_json& attempt : test["retryAttempts"]) {
                renameOldExtension(attempt);
            }
        }
    }
}

void readJsonShape(Report& report, const Place& place) {
    const auto& document = report.json;
    if (!document.is_object() || !document.contains("reportFormat") ||
        document["reportFormat"] != "CTRF" || !document.contains("generatedBy") ||
        document["generatedBy"] != runnerName || !document.contains("results") ||
        !document["results"].is_object() || !document["results"].contains("tests") ||
        !document["results"]["tests"].is_array()) {
        throw place.error(-1, std::string("not a JSON (CTRF) output of this runner (expected "
                                          "\"generatedBy\": \"") +
                                  runnerName + "\" and results.tests)");
    }
    renameOldExtensions(report.json);
    const auto& results = document["results"];
    readJsonRun(document, place);
    const auto extra =
        results.value("/extra/robotology.rtf"_json_pointer, nlohmann::ordered_json::object());
    if (extra.contains("shard")) {
        const auto& shard = extra["shard"];
        if (!shard.is_object() || !shard.contains("index") || !shard.contains("count") ||
            !shard["index"].is_number_unsigned() || !shard["count"].is_number_unsigned()) {
            throw place.error(
                -1,
                "results.extra.robotology.rtf.shard: expected {\"index\": I, \"count\": "
                "N} with whole numbers");
        }
        report.shard.known = true;
        report.shard.index = shard["index"].get<unsigned int>();
        report.shard.count = shard["count"].get<unsigned int>();
        if (shard.contains("plan")) {
            if (!shard["plan"].is_string()) {
                throw place.error(-1, "results.extra.robotology.rtf.shard.plan: expected a string");
            }
            report.shard.plan = shard["plan"].get<std::string>();
        }
    }
    if (extra.contains("rerun") && !extra["rerun"].is_boolean()) {
        throw place.error(-1, "results.extra.robotology.rtf.rerun: expected true or false");
    }
    report.shard.rerun = extra.value("rerun", false);
    checkShard(report.shard, place, -1);
    const auto& tests = results["tests"];
    for (std::size_t i = 0; i < tests.size(); ++i) {
        const auto& test = tests[i];
        const std::string where = "results.tests[" + std::to_string(i) + "]";
        if (!test.is_object() || !test.contains("name") || !test["name"].is_string() ||
            !test.contains("duration") || !test["duration"].is_number() ||
            !test.contains("status") || !test["status"].is_string() ||
            !ctrfStatus(test["status"].get<std::string>()) || !test.contains("testId") ||
            !test["testId"].is_string() || !isTestId(test["testId"].get<std::string>()) ||
            !test.contains("/extra/robotology.rtf/state"_json_pointer) ||
            !test["extra"][ctrfExtensionKey]["state"].is_string() ||
            !knownState(test["extra"][ctrfExtensionKey]["state"].get<std::string>())) {
            throw place.error(-1, where +
                                      ": expected a test with a name, a CTRF status, a testId "
                                      "\"S.T\" (its place in the run), a duration and "
                                      "extra.robotology.rtf.state");
        }
        std::string suite;
        if (test.contains("suite")) {
            if (!test["suite"].is_array() || test["suite"].size() != 1 ||
                !test["suite"][0].is_string()) {
                throw place.error(-1, where + ".suite: expected [\"suite name\"]");
            }
            suite = test["suite"][0].get<std::string>();
        }
        ReportedTest reportedTest{suite, test["name"].get<std::string>(),
                                  test["extra"][ctrfExtensionKey]["state"].get<std::string>()};
        reportedTest.seconds = test["duration"].get<double>() / 1000.0;
        if (test.contains("retries") && test["retries"].is_number_unsigned()) {
            reportedTest.attempts += test["retries"].get<unsigned int>();
        }
        report.tests.push_back(reportedTest);
    }
    // Each suite's time: the report's own when it has them (fixtures included), else its tests'.
    if (extra.contains("suites")) {
        const auto& suites = extra["suites"];
        for (std::size_t i = 0; i < (suites.is_array() ? suites.size() : 0); ++i) {
            const auto& suite = suites[i];
            if (!suite.is_object() || !suite.contains("name") || !suite["name"].is_string() ||
                !suite.contains("place") || !suite["place"].is_number_unsigned() ||
                !suite.contains("duration") || !suite["duration"].is_number() ||
                suite["duration"].get<double>() < 0) {
                throw place.error(
                    -1, "results.extra.robotology.rtf.suites[" + std::to_string(i) +
                            "]: expected {\"place\": N, \"name\": ..., \"duration\": ms}");
            }
            report.suites.push_back(
                {suite["name"].get<std::string>(), suite["duration"].get<double>() / 1000.0});
        }
        if (!suites.is_array()) {
            throw place.error(-1, "results.extra.robotology.rtf.suites: expected an array");
        }
        return;
    }
    for (std::size_t i = 0; i < tests.size(); ++i) {
        const std::string suite = report.tests[i].suite;
        auto found = std::find_if(report.suites.begin(), report.suites.end(),
                                  [&](const ReportedSuite& known) { return known.name == suite; });
        if (found == report.suites.end()) {
            report.suites.push_back({suite, 0});
            found = report.suites.end() - 1;
        }
        found->seconds += tests[i]["duration"].get<double>() / 1000.0;
    }
}

}  // namespace

Report readReport(const std::string& option, const std::string& path) {
    std::string text;
    std::string error;
    if (!platform::readBoundedFile(path, "report", maxReportBytes, platform::Pipes::Read, text,
                                   error)) {
        throw std::runtime_error(option + " " + error);
    }
    return parseReport(option, text, path);
}

Report parseReport(const std::string& option, const std::string& text, const std::string& path) {
    const Place place(option, path, text);
    Report report;
    report.path = path;
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && text[first] == '<') {
        report.format = ReportFormat::JUnit;
        readJUnit(report, text, place);
    } else if (first != std::string::npos && text[first] == '{') {
        report.format = ReportFormat::Json;
        readJson(report, text, place);
    } else {
        throw place.error(-1, "not a JUnit (XML) or JSON (CTRF) output of this runner");
    }
    return report;
}

}  // namespace runner
}  // namespace robottestingframework
