// What a run starts from once the command line is read: its suites read and checked, the shard
// chosen, the resource pools, the command line's overrides.
#pragma once

#include <vector>

#include "runner/cli/options.h"
#include "runner/model/suite_model.h"
#include "runner/plan/run_plan.h"
#include "runner/plan/shard_of_this_machine.h"
#include "runner/schedule/resources.h"

namespace robottestingframework {
namespace runner {

struct RunInputs {
    std::vector<SuiteSpec> suites;  // as read, in the command line's order
    ShardChoice shard;
    ResourcePools pools;
    Overrides overrides;
};

// Reads the suites (their warnings on stderr), chooses the shard (prepareShard: it may add an
// output to `options`), warns of --var nothing reads, and checks the dependencies, the output
// paths, the resource pools and the world files of process fixtures (world_files.h). False,
// the error said on stderr, on a configuration error.
bool readRunInputs(Options& options, RunInputs& inputs);

}  // namespace runner
}  // namespace robottestingframework
