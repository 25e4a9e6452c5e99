#include "runner/history/history_trends.h"

#include <algorithm>
#include <cmath>

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

double noiseFloor(double before, const std::vector<double>& olderTimes) {
    double spread = 0;
    if (!olderTimes.empty()) {
        std::vector<double> deviations;
        for (const double time : olderTimes) {
            deviations.push_back(std::fabs(time - before));
        }
        spread = 3 * median(deviations);
    }
    return std::max({absoluteNoiseSeconds, relativeNoise * before, spread});
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
    const std::vector<double> older(times.begin(), split);
    Slowdown slowdown;
    slowdown.before = median(older);
    slowdown.recent = median({split, times.end()});
    slowdown.noise = noiseFloor(slowdown.before, older);
    return slowdown;
}

bool alwaysFails(const TestHistory& history) {
    std::size_t runs = 0;
    for (const TestHistoryEntry& entry : history.runs) {
        if (!counts(entry.state)) {
            continue;
        }
        if (passing(entry.state)) {
            return false;
        }
        ++runs;
    }
    return runs >= 2;
}

double medianSeconds(const TestHistory& history) {
    std::vector<double> times;
    for (const TestHistoryEntry& entry : history.runs) {
        if (entry.state != "skipped") {
            times.push_back(entry.duration);
        }
    }
    return times.empty() ? 0 : median(times);
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
        if (slowdown.slowedDown()) {
            found.push_back({&history, slowdown});
        }
    }
    std::stable_sort(found.begin(), found.end(), [](const SlowedTest& a, const SlowedTest& b) {
        return a.slowdown.ratio() > b.slowdown.ratio();
    });
    found.resize(std::min(found.size(), limit));
    return found;
}

std::vector<const TestHistory*> alwaysFailingTests(const std::vector<TestHistory>& histories) {
    std::vector<const TestHistory*> found;
    for (const TestHistory& history : histories) {
        if (alwaysFails(history)) {
            found.push_back(&history);
        }
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const TestHistory* a, const TestHistory* b) { return a->test < b->test; });
    return found;
}

std::vector<const TestHistory*> slowestByMedian(const std::vector<TestHistory>& histories,
                                                std::size_t limit) {
    std::vector<std::pair<const TestHistory*, double>> timed;
    for (const TestHistory& history : histories) {
        timed.emplace_back(&history, medianSeconds(history));
    }
    std::stable_sort(timed.begin(), timed.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    std::vector<const TestHistory*> found;
    for (std::size_t i = 0; i < timed.size() && i < limit; ++i) {
        found.push_back(timed[i].first);
    }
    return found;
}

}  // namespace runner
}  // namespace robottestingframework
