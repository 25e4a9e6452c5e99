#include "runner/cli/world_join.h"

#include <cstdio>

#include "runner/cli/program_name.h"

namespace robottestingframework {
namespace runner {

bool joinWorldOfOptions(const Options& options, PlannedRun& planned, KeptWorld& kept) {
    if (options.world.empty()) {
        return true;
    }
    std::string error;
    if (planned.suites.size() != 1) {
        std::fprintf(stderr, "%s: --world %s: expected one suite (--suite FILE), got %zu\n",
                     programName, options.world.c_str(), planned.suites.size());
        return false;
    }
    if (!joinKeptWorld(options.world, planned.suites.front().name, kept, error)) {
        std::fprintf(stderr, "%s: --world %s: %s\n", programName, options.world.c_str(),
                     error.c_str());
        return false;
    }
    planned.suites.front().fixtures.clear();
    planned.suites.front().network =
        kept.network ? SuiteSpec::Network::Private : SuiteSpec::Network::Host;
    return true;
}

}  // namespace runner
}  // namespace robottestingframework
