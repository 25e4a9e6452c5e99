// Each suite's time from an earlier run, for --durations-from (shard balancing, the ETA): read from
// a JUnit or JSON report of this runner, or from a --history file (each suite's latest run).
#pragma once

#include <map>
#include <string>

namespace robottestingframework {
namespace runner {

// Suite name -> seconds.
using SuiteSeconds = std::map<std::string, double>;

// Throws std::runtime_error "--durations-from FILE: ..." when the file cannot be read.
SuiteSeconds suiteDurations(const std::string& file);

}  // namespace runner
}  // namespace robottestingframework
