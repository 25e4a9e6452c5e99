// What a world keeper (--world-up DIR) and the runners that use its world (--world DIR,
// --world-down DIR) say to each other over its control socket: one packet each way. Plain text,
// so that the keeper's log and a test can read it; the private network's descriptors travel
// beside the answer (SCM_RIGHTS). Pure logic: world_keeper-posix.cpp does the talking.
#pragma once

#include <string>

namespace robottestingframework {
namespace runner {

// The name of a suite that only holds shared worlds for other suites (the suite file that
// robottestingframework_discover_tests writes for a shared world's keeper): --world DIR takes
// such a keeper's world for any suite.
constexpr const char* sharedWorldKeeperPrefix = "shared world ";

// The control socket and the keeper's log in a keeper's folder.
std::string worldSocketPath(const std::string& folder);
std::string worldLogPath(const std::string& folder);
// Written by --world-up when its world failed to start (the reason, as it printed it), removed
// when a world is set up there again: --world-down then has nothing to stop, and says so with
// worldNeverStarted, so that CTest counts the world's failure once, in its world:up test.
std::string worldFailedPath(const std::string& folder);

// A request: "status" (is the world up? its network) or "down" (tear it down and say how).
enum class WorldRequest { Status, Down, Unknown };
WorldRequest parseWorldRequest(const std::string& packet);
std::string worldRequestText(WorldRequest request);

// The keeper's answer to "status".
struct WorldStatus {
    enum class State { Starting, Up, Collapsed, Stopping };
    State state = State::Starting;
    // How many descriptors of a private network come with the answer: 0 (the machine's
    // network), 1 (a network namespace) or 2 (a user namespace, then a network namespace).
    unsigned int networkDescriptors = 0;
    std::string reason;  // Collapsed: the world's reason (may span lines)
    std::string suite;   // whose world it is (the suite's name, one line)
};
std::string worldStatusText(const WorldStatus& status);
// False when `packet` is not an answer to "status" (a keeper of another version).
bool parseWorldStatus(const std::string& packet, WorldStatus& status);

// The keeper's answer to "down", and what it tells the --world-up runner when its set-up
// ended: passed or not, and what a run prints about the world (its errors, one a line).
struct WorldOutcome {
    bool passed = false;
    std::string text;
};
std::string worldOutcomeText(const WorldOutcome& outcome);
bool parseWorldOutcome(const std::string& packet, WorldOutcome& outcome);

}  // namespace runner
}  // namespace robottestingframework
