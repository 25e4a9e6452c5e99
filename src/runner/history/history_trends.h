// What a test's recent runs say about it: how flaky it is and how much slower it got. Pure
// functions of its history (history_queries.h), shared by --history-report and the pages.
#pragma once

#include <cstddef>
#include <vector>

#include "runner/history/history_queries.h"

namespace robottestingframework {
namespace runner {

// The share (0 to 1) of its runs that were flaky (passed on a retry) or whose outcome, passing
// or failing, differs from the run before. Skipped and interrupted runs do not count.
double flakyRate(const TestHistory& history);

struct Slowdown {
    double before = 0;  // seconds: the median of its older runs
    double recent = 0;  // seconds: the median of its newest third
    // Seconds: how much slower it must get to be a slow-down rather than noise (noiseFloor).
    double noise = 0;
    double ratio() const { return before > 0 ? recent / before : 0; }
    bool slowedDown() const { return before > 0 && recent - before > noise; }
};

// The noise floor a slow-down is judged against: the largest of an absolute floor (0.1 s: a
// loaded machine, -j N, delays a short test by that much), a relative one (20 % of `before`)
// and 3 times the median absolute deviation of the older runs' times (the test's own spread).
constexpr double absoluteNoiseSeconds = 0.1;
constexpr double relativeNoise = 0.2;
double noiseFloor(double before, const std::vector<double>& olderTimes);

// The median time of its newest third of runs against its older runs'; none (both 0) with
// fewer than 3 timed runs. Skipped runs do not count.
Slowdown slowdownOf(const TestHistory& history);

// Whether every one of its runs (skipped and interrupted ones aside, at least 2) failed.
bool alwaysFails(const TestHistory& history);
// Its median time over its runs (skipped ones aside); 0 with none.
double medianSeconds(const TestHistory& history);

struct FlakyTest {
    const TestHistory* history;
    double rate;
};
struct SlowedTest {
    const TestHistory* history;
    Slowdown slowdown;
};

// The `limit` flakiest tests (rate above 0), flakiest first, then by id.
std::vector<FlakyTest> flakiestTests(const std::vector<TestHistory>& histories, std::size_t limit);
// The `limit` tests that slowed down most (recent over before, beyond the noise floor: a
// loaded machine's noise is not a slow-down), most first, then by id.
std::vector<SlowedTest> mostSlowedTests(const std::vector<TestHistory>& histories,
                                        std::size_t limit);
// The tests that failed every run (alwaysFails), by id.
std::vector<const TestHistory*> alwaysFailingTests(const std::vector<TestHistory>& histories);
// The `limit` slowest tests by their median time, slowest first, then by id.
std::vector<const TestHistory*> slowestByMedian(const std::vector<TestHistory>& histories,
                                                std::size_t limit);

}  // namespace runner
}  // namespace robottestingframework
