// --merge OUT_TYPE:OUT_FILE REPORT...: the shards' reports merged into one; runs nothing.
#pragma once

#include "runner/cli/options.h"

namespace robottestingframework {
namespace runner {

// Merges, says so on stdout and returns allPassed; on an error, says it on stderr and returns
// configurationError.
int mergeCommand(const Options& options);

}  // namespace runner
}  // namespace robottestingframework
