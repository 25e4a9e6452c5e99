#include "runner/history/history_trends.h"

#include <algorithm>

namespace robottestingframework {
namespace runner {

namespace {

bool counts(const std::string& state) {
    return state != "skipped" && state != "interrupted";
}
bool passing(const std::string& state) {
    return state == "passed" || state == "flaky";
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2;
}

}  // namespace

double flakyRate(const TestHistory& history) {
    std::size_t runs = 0;
    std::size_t flaky = 0;
    const TestHistoryEntry* previous = nullptr;
    for (const TestHistoryEntry& entry : history.runs) {
        if (!counts(entry.state)) {
            continue;
        }
        ++runs;
        if (entry.state == "flaky" ||
            (previous != nullptr && passing(previous->state) != passing(entry.state))) {
            ++flaky;
        }
        previous = &entry;
    }
    return runs == 0 ? 0 : static_cast<double>(flaky) / static_cast<double>(runs);
}

Slowdown slowdownOf(const TestHistory& history) {
    std::vector<double> times;
    for (const TestHistoryEntry& entry : history.runs) {
        if (entry.state != "skipped") {
            times.push_back(entry.duration);
        }
    }
    if (times.size() < 3) {
        return {};
    }
    const std::size_t recent = std::max<std::size_t>(1, times.size() / 3);
    const auto split = times.end() - static_cast<std::ptrdiff_t>(recent);
    return {median({times.begin(), split}), median({split, times.end()})};
}

std::vector<FlakyTest> flakiestTests(const std::vector<TestHistory>& histories, std::size_t limit) {
    std::vector<FlakyTest> found;
    for (const TestHistory& history : histories) {
        const double rate = flakyRate(history);
        if (rate > 0) {
            found.push_back({&history, rate});
        }
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const FlakyTest& a, const FlakyTest& b) { return a.rate > b.rate; });
    found.resize(std::min(found.size(), limit));
    return found;
}

std::vector<SlowedTest> mostSlowedTests(const std::vector<TestHistory>& histories,
                                        std::size_t limit) {
    std::vector<SlowedTest> found;
    for (const TestHistory& history : histories) {
        const Slowdown slowdown = slowdownOf(history);
        if (slowdown.before > 0 && slowdown.recent >= 1.2 * slowdown.before &&
            slowdown.recent - slowdown.before >= 0.05) {
            found.push_back({&history, slowdown});
        }
    }
    std::stable_sort(found.begin(), found.end(), [](const SlowedTest& a, const SlowedTest& b) {
        return a.slowdown.ratio() > b.slowdown.ratio();
    });
    found.resize(std::min(found.size(), limit));
    return found;
}

}  // namespace runner
}  // namespace robottestingframework
