// --history FILE --history-import REPORT...: loads earlier JUnit or CTRF reports (this
// runner's or another tool's) into the history, one run each, and exits: 0, or 2 naming the
// first report or history file that cannot be read (nothing of that report is loaded).
#pragma once

#include "runner/cli/options.h"

namespace robottestingframework {
namespace runner {

int historyImportCommand(const Options& options);

}  // namespace runner
}  // namespace robottestingframework
