// --history-report N --history-html FILE: the history report as one self-contained HTML page
// (no script, no link outside it): each test's outcomes and times over the runs, its flaky rate,
// the tests that always fail, the slowest, the slow-downs beyond the noise floor, and the
// measurements over the runs.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "runner/history/history_queries.h"

namespace robottestingframework {
namespace runner {

// `runs`: the runs read of the `asked`.
std::string historyReportHtml(const std::vector<TestHistory>& histories,
                              const RecentMeasurements& measurements, std::size_t runs,
                              unsigned int asked);

}  // namespace runner
}  // namespace robottestingframework
