// A run's private networks (<suite network="private">, --network private), checked before the
// run starts: --network private gives every suite one, and when any suite has one, one is made
// and dropped here, so that a machine that cannot have them stops the run (exit 2) with the
// kernel's reason instead of running a suite in the machine's network.
#pragma once

#include <string>
#include <vector>

#include "runner/cli/options.h"
#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

// False with `error` when a suite's private network cannot be had (or, with --isolation none,
// joined by the runner's thread). `note`: what making one cost, for --verbose.
bool preparePrivateNetworks(const Options& options, std::vector<SuiteSpec>& suites,
                            std::string& error, std::string& note);

// The same, saying the error on stderr and, with --verbose, the cost on stdout.
bool setUpPrivateNetworks(const Options& options, std::vector<SuiteSpec>& suites);

}  // namespace runner
}  // namespace robottestingframework
