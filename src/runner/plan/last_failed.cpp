#include "runner/plan/last_failed.h"

#include <algorithm>

#include "runner/model/test_id.h"

namespace robottestingframework {
namespace runner {

std::size_t countTestsNamed(const std::vector<SuiteSpec>& suites,
                            const std::set<std::string>& ids) {
    std::size_t count = 0;
    for (const auto& suite : suites) {
        for (const auto& test : suite.tests) {
            count += ids.count(testId(suite, test));
        }
    }
    return count;
}

void keepTestsNamed(std::vector<SuiteSpec>& suites, const std::set<std::string>& ids) {
    std::vector<SuiteSpec> chosen;
    for (auto& suite : suites) {
        std::vector<TestSpec> tests;
        for (auto& test : suite.tests) {
            if (ids.count(testId(suite, test)) != 0) {
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

void putTestsNamedFirst(std::vector<SuiteSpec>& suites, const std::set<std::string>& ids) {
    auto failedIn = [&ids](const SuiteSpec& suite, const TestSpec& test) {
        return ids.count(testId(suite, test)) != 0;
    };
    for (auto& suite : suites) {
        const bool ordered =
            std::any_of(suite.tests.begin(), suite.tests.end(),
                        [](const TestSpec& test) { return !test.depends.empty(); });
        if (!ordered) {
            std::stable_partition(suite.tests.begin(), suite.tests.end(),
                                  [&](const TestSpec& test) { return failedIn(suite, test); });
        }
    }
    std::stable_partition(suites.begin(), suites.end(), [&](const SuiteSpec& suite) {
        return std::any_of(suite.tests.begin(), suite.tests.end(),
                           [&](const TestSpec& test) { return failedIn(suite, test); });
    });
}

}  // namespace runner
}  // namespace robottestingframework
