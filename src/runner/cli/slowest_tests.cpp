#include "runner/cli/slowest_tests.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "reporters/summary.h"

namespace robottestingframework {
namespace runner {

namespace {

struct Timed {
    const SuiteRecord* suite;
    const TestRecord* test;
};

}  // namespace

std::string slowestTestsText(const TestResultCollector& collector, int count) {
    std::vector<Timed> ran;
    for (const SuiteRecord& suite : collector.suites()) {
        for (const TestRecord& test : suite.tests) {
            if (test.status != TestStatus::Skipped) {
                ran.push_back({&suite, &test});
            }
        }
    }
    if (ran.empty() || count < 0) {
        return {};
    }
    // Slowest first; equal times in the run's order.
    std::stable_sort(ran.begin(), ran.end(), [](const Timed& a, const Timed& b) {
        return a.test->duration > b.test->duration;
    });
    const std::size_t shown =
        count == 0 ? ran.size() : std::min(ran.size(), static_cast<std::size_t>(count));
    std::string text = count == 0 ? "the " + std::to_string(ran.size()) + " tests, slowest first:\n"
                                  : "slowest " + std::to_string(shown) + " of " +
                                        std::to_string(ran.size()) + " tests:\n";
    for (std::size_t i = 0; i < shown; ++i) {
        const TestRecord& test = *ran[i].test;
        const std::string& name = test.reportName();
        const std::string id = ran[i].suite->name.empty() ? name : ran[i].suite->name + "/" + name;
        char time[64];
        std::snprintf(time, sizeof time, "%10.3f s  %-10s", test.duration,
                      reporters::statusWord(test.status));
        text += std::string(time) + " " + id + "\n";
    }
    return text;
}

}  // namespace runner
}  // namespace robottestingframework
