// Why a test did not run to its end, in the words every output shows after the event's kind
// ("interrupted: ...", "skipped: ..."): the message says what happened, not the kind's word
// again, and a fixture's failure is said once, by its suite (with its whole reason), each test
// it kept from running referring to it in one line. The isolated executor says
// stoppedWhileRunning too, so a test reads the same in process and in a worker.
#pragma once

#include <string>

#include <robottestingframework/TestMessage.h>

#include "core/text_safety.h"

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

// What a test kept from running by its suite's fixture says: `what` (fixtureFailed or
// fixtureCollapsed), then the first line of the fixture's failure, so that each skipped test
// of a report read alone (a Jenkins or GitLab page of one test case) still says why; the rest
// of the reason (its other lines, the log's tail) is the suite's error only.
inline TestMessage fixtureReason(const char* what, const TestMessage& failure) {
    std::string first = failure.getMessage();
    first = first.substr(0, first.find('\n'));
    constexpr std::size_t most = 200;  // a line, not a page
    if (first.size() > most) {
        // Cut between characters: a split UTF-8 character is an invalid byte in every report.
        first = first.substr(0, reporters::characterBoundary(first, most)) + "...";
    }
    return TestMessage(first.empty() ? std::string(what) : std::string(what) + ": " + first);
}

}  // namespace notrun
}  // namespace robottestingframework
