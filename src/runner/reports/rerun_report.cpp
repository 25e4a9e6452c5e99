#include "runner/reports/rerun_report.h"

#include <algorithm>

#include "runner/model/test_id.h"

namespace robottestingframework {
namespace runner {

namespace {

// The states a rerun takes again, as the reports spell them (TestStatus's toString).
bool rerunState(const std::string& state) {
    return state == "failed" || state == "error" || state == "crashed" || state == "timed out";
}

}  // namespace

std::vector<FailedTest> failedTests(const Report& report) {
    std::vector<FailedTest> failed;
    for (const ReportedTest& test : report.tests) {
        if (rerunState(test.state)) {
            failed.push_back({test.suite, test.name});
        }
    }
    return failed;
}

std::vector<FailedTest> readFailedTests(const std::string& path) {
    return failedTests(readReport("--rerun-failed", path));
}

std::vector<FailedTest> parseFailedTests(const std::string& text, const std::string& path) {
    return failedTests(parseReport("--rerun-failed", text, path));
}

bool isStopRecord(const std::string& name) {
    return name.rfind("world '", 0) == 0 && name.find("': stop of '") != std::string::npos &&
           name.back() == '\'';
}

void keepFailedTests(std::vector<SuiteSpec>& suites, const std::vector<FailedTest>& failed) {
    std::vector<SuiteSpec> chosen;
    for (auto& suite : suites) {
        // A process of its world that did not stop cleanly: the whole suite runs again, and
        // its world with it.
        const bool whole =
            !suite.tests.empty() &&
            std::any_of(failed.begin(), failed.end(), [&](const FailedTest& other) {
                return isStopRecord(other.test) &&
                       testId(suite, suite.tests.front()).rfind(other.suite + "/", 0) == 0;
            });
        std::vector<TestSpec> tests;
        for (auto& test : suite.tests) {
            const bool named =
                whole || std::any_of(failed.begin(), failed.end(), [&](const FailedTest& other) {
                    // Reports name a test by its id (model/test_id.h), never by the name it
                    // gives itself, so a renamed, repeated or moved test is found again.
                    return testId(suite, test) == other.suite + "/" + other.test;
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
