// Why a test did not run to its end, in the words every output shows after the event's kind
// ("interrupted: ...", "skipped: ..."): the message says what happened, not the kind's word
// again, and a fixture's failure is said once, by its suite (with its whole reason), each test
// it kept from running referring to it in one line. The isolated executor says
// stoppedWhileRunning too, so a test reads the same in process and in a worker.
#pragma once

namespace robottestingframework {
namespace notrun {

// A test the run never started: Ctrl-C, SIGTERM or --fail-fast stopped the run first.
inline constexpr const char* interrupted = "not run: the run was stopped before it started";
// A test stopped while it ran (its kind, "interrupted", comes before).
inline constexpr const char* stoppedWhileRunning = "stopped while running";
// The tests after a fixture of their suite failed to set up, or collapsed.
inline constexpr const char* fixtureFailed = "the suite's fixture failed (see the suite's error)";
inline constexpr const char* fixtureCollapsed =
    "the suite's fixture collapsed (see the suite's error)";

}  // namespace notrun
}  // namespace robottestingframework
