// One world per suite under CTest (docs/how-to/ctest-worlds.md). --world-up DIR sets up the suite's
// fixtures (its world, in its private network when it has one) in a keeper: a process of its
// own session that outlives the runner which started it, with a control socket in DIR
// (world_protocol.h). The runner returns once the set-up ended and prints what a run prints
// about it. The keeper watches its world as a suite does (a collapse is remembered and told to
// the runners that ask), and tears it down when --world-down DIR asks, when it is interrupted
// (SIGINT, SIGTERM), or when the process that started the --world-up runner (ctest) is gone,
// whatever way it ended. -posix: the keeper; -windows: not supported (exit 2).
#pragma once

#include "runner/cli/options.h"
#include "runner/cli/planned_run.h"
#include "runner/cli/run_inputs.h"

namespace robottestingframework {
namespace runner {

// --world-up DIR: 0 when the world is up, 1 when its set-up failed, 2 on bad input (not one
// suite, a keeper already at DIR, a folder that cannot be made).
int worldUpCommand(Options& options, PlannedRun& planned, RunInputs& inputs);

// --world-down DIR: 0 when the tear-down passed, 1 when it failed (or the world had
// collapsed), 2 when no keeper is at DIR.
int worldDownCommand(const Options& options);

}  // namespace runner
}  // namespace robottestingframework
