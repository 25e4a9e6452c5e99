// Running the plan: the scheduler (-j N, resource pools), --repeat-until-fail's rounds, and
// Ctrl-C or SIGTERM stopping them in order.
#pragma once

#include <memory>

#include "runner/cli/options.h"
#include "runner/cli/run_listeners.h"
#include "runner/plan/run_plan.h"
#include "runner/schedule/resources.h"

namespace robottestingframework {
namespace runner {

// Runs every suite of `plan` into `listeners`, once or, with --repeat-until-fail N, round after
// round until one fails (each round is in the outputs, one after the other). Returns the
// signal that interrupted the run, 0 when none. `network`: the private network a --world
// keeper gave (nullptr: each suite that asks for one gets a new one).
int runRounds(const Options& options, RunPlan& plan, ResourcePools pools, RunListeners& listeners,
              std::shared_ptr<const platform::PrivateNetwork> network = nullptr);

}  // namespace runner
}  // namespace robottestingframework
