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
    double ratio() const { return before > 0 ? recent / before : 0; }
};

// The median time of its newest third of runs against its older runs'; none (both 0) with
// fewer than 3 timed runs. Skipped runs do not count.
Slowdown slowdownOf(const TestHistory& history);

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
// The `limit` tests that slowed down most (recent over before, at least 1.2 times and 50 ms
// slower: a loaded machine's noise is not a slowdown), most first, then by id.
std::vector<SlowedTest> mostSlowedTests(const std::vector<TestHistory>& histories,
                                        std::size_t limit);

}  // namespace runner
}  // namespace robottestingframework
