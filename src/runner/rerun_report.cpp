#include "rerun_report.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "plugin_test.h"

namespace robottestingframework {
namespace runner {

namespace {

const char* const runnerName = "robottestingframework-testrunner";

// The states a rerun takes again, as the reports spell them (TestStatus's toString).
bool rerunState(const std::string& state) {
    return state == "failed" || state == "error" || state == "crashed" || state == "timed out";
}

std::vector<FailedTest> fromJUnit(const std::string& path, const std::string& text) {
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_string(text.c_str());
    if (!parsed) {
        throw std::runtime_error("--rerun-failed " + path + ": not valid XML (" +
                                 parsed.description() + " at byte " +
                                 std::to_string(parsed.offset) + ")");
    }
    const pugi::xml_node root = document.document_element();
    if (std::string(root.name()) != "testsuites" ||
        std::string(root.attribute("name").value()) != "RobotTestingFramework") {
        throw std::runtime_error("--rerun-failed " + path +
                                 ": not a JUnit output of this runner (expected <testsuites "
                                 "name=\"RobotTestingFramework\">)");
    }
    std::vector<FailedTest> failed;
    for (const pugi::xml_node suite : root.children("testsuite")) {
        for (const pugi::xml_node test : suite.children("testcase")) {
            // A failed fixture has a <testcase> of its own: its tests were skipped, not failed.
            if (std::string(test.child("error").attribute("type").value()) == "fixture") {
                continue;
            }
            if (rerunState(test.attribute("status").value())) {
                const std::string suiteName = suite.attribute("name").value();
                failed.push_back(
                    {suiteName == "default" ? "" : suiteName, test.attribute("name").value()});
            }
        }
    }
    return failed;
}

std::vector<FailedTest> fromJson(const std::string& path, const std::string& text) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error("--rerun-failed " + path + ": not valid JSON (" + e.what() + ")");
    }
    // value() would throw a bare type error for a "reportFormat" that is not a string.
    if (!document.is_object() || !document["reportFormat"].is_string() ||
        document["reportFormat"] != "CTRF" || !document["generatedBy"].is_string() ||
        document["generatedBy"] != runnerName || !document["results"].is_object() ||
        !document["results"]["tests"].is_array()) {
        throw std::runtime_error("--rerun-failed " + path +
                                 ": not a JSON (CTRF) output of this runner (expected "
                                 "\"generatedBy\": \"" +
                                 runnerName + "\" and results.tests)");
    }
    std::vector<FailedTest> failed;
    std::size_t index = 0;
    for (const auto& test : document["results"]["tests"]) {
        // value() throws a bare type error for a test that is not an object or a state or
        // name that is not a string: say which test of which file.
        try {
            const auto state = test.value("/extra/rtf/state"_json_pointer, std::string());
            if (rerunState(state)) {
                std::string suite;
                if (test.contains("suite") && test["suite"].is_array() && !test["suite"].empty() &&
                    test["suite"][0].is_string()) {
                    suite = test["suite"][0].get<std::string>();
                }
                failed.push_back({suite, test.value("name", std::string())});
            }
        } catch (const nlohmann::json::exception& e) {
            throw std::runtime_error("--rerun-failed " + path + ": results.tests[" +
                                     std::to_string(index) +
                                     "] is not a test of this runner (expected an object with "
                                     "a string \"name\" and extra.rtf.state; " +
                                     e.what() + ")");
        }
        ++index;
    }
    return failed;
}

}  // namespace

std::vector<FailedTest> readFailedTests(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error("--rerun-failed " + path + ": cannot read the report");
    }
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return parseFailedTests(buffer.str(), path);
}

std::vector<FailedTest> parseFailedTests(const std::string& text, const std::string& path) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && text[first] == '<') {
        return fromJUnit(path, text);
    }
    if (first != std::string::npos && text[first] == '{') {
        return fromJson(path, text);
    }
    throw std::runtime_error("--rerun-failed " + path +
                             ": not a JUnit (XML) or JSON (CTRF) output of this runner");
}

void keepFailedTests(std::vector<SuiteSpec>& suites, const std::vector<FailedTest>& failed) {
    std::vector<SuiteSpec> chosen;
    for (auto& suite : suites) {
        std::vector<TestSpec> tests;
        for (auto& test : suite.tests) {
            const bool named =
                std::any_of(failed.begin(), failed.end(), [&](const FailedTest& other) {
                    return other.suite == suite.name &&
                           (other.test == test.name || other.test == PluginTest::displayName(test));
                });
            if (named) {
                test.depends.clear();  // what it depends on passed in the earlier run
                tests.push_back(std::move(test));
            }
        }
        if (!tests.empty()) {
            suite.tests = std::move(tests);
            chosen.push_back(std::move(suite));
        }
    }
    suites = std::move(chosen);
}

}  // namespace runner
}  // namespace robottestingframework
