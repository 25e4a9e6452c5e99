// Stopping a process and everything it started: its process group, and (Linux, /proc) every
// descendant, frozen first so that none can fork a new one while we look.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <vector>

namespace robottestingframework {
namespace platform {

// Sends `signal` to every process of group `group`; false when there is no such group.
bool signalProcessGroup(pid_t group, int signal);

// Every living descendant of `root` (children, their children, ...), parents before children.
std::vector<pid_t> descendantsOf(pid_t root);

// Freezes (SIGSTOP) every descendant of `root`, again until no new one appears, then kills them
// all (SIGKILL). Zombies are left for their parent to reap. Returns how many were killed.
std::size_t killDescendants(pid_t root);

// Our child `leader` heads a process group: SIGTERM to the group, up to `grace` seconds for
// the leader to end, then SIGKILL to the group. Reaps the leader and returns its wait status.
int stopChildGroup(pid_t leader, double grace);

}  // namespace platform
}  // namespace robottestingframework
