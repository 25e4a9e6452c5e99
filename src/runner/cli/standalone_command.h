// The commands that are not a run: --merge, --history-import, --history-report and
// --world-down. Each reads what it needs from the options and exits.
#pragma once

#include <optional>

#include "runner/cli/options.h"

namespace robottestingframework {
namespace runner {

// The exit status of the command the options ask for; none when they ask for a run (or a list,
// or --world-up, which read the suites first).
std::optional<int> standaloneCommand(const Options& options);

}  // namespace runner
}  // namespace robottestingframework
