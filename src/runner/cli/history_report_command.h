// --history FILE --history-report [N]: prints the flakiest and the most slowed-down tests of
// the file's last N runs, and exits (0; 2 when the file cannot be read).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "runner/cli/options.h"
#include "runner/history/history_queries.h"

namespace robottestingframework {
namespace runner {

int historyReportCommand(const Options& options);

// What the command prints: `runs` the runs the file has of the `asked`.
std::string historyReportText(const std::vector<TestHistory>& histories, std::size_t runs,
                              unsigned int asked);

}  // namespace runner
}  // namespace robottestingframework
