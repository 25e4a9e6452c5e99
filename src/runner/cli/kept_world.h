// --world DIR: a run of a suite's tests in the world a keeper holds (world_keeper.h) instead of
// the suite's own fixtures. The keeper is asked before the run (no keeper: exit 2; its private
// network's descriptors come back, and the run's suites join that network), and the suite gets
// one stand-in fixture whose set-up fails with the world's reason when the world collapsed or
// is stopping, and which tells the suite of a collapse while its tests run, as a world of its
// own would. -posix; -windows: not supported.
#pragma once

#include <memory>
#include <string>

#include <robottestingframework/FixtureManager.h>

namespace robottestingframework {
namespace platform {
class PrivateNetwork;
}  // namespace platform
namespace runner {

struct KeptWorld {
    // The keeper's network; nullptr when the suite lives in the machine's.
    std::shared_ptr<const platform::PrivateNetwork> network;
    // The stand-in for the suite's fixtures (named after the keeper's folder).
    std::unique_ptr<FixtureManager> fixture;
};

// Asks the keeper at `folder` for the world of suite `suite`. False with `error` when none
// answers there, or when it keeps another suite's world.
bool joinKeptWorld(const std::string& folder, const std::string& suite, KeptWorld& world,
                   std::string& error);

}  // namespace runner
}  // namespace robottestingframework
