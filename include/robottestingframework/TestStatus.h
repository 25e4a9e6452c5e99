// The final state of a test, as every output shows it.
#pragma once

namespace robottestingframework {

// Ordered by precedence: when a test collects several outcomes, the highest one is its state.
enum class TestStatus {
    Passed = 0,
    Skipped,
    Failed,
    Error,
    Crashed,
    TimedOut,
    Interrupted,
    // Passed on a later attempt (--retries) after failing: never given by an event, so last.
    Flaky,
};

// "passed", "skipped", "failed", "error", "crashed", "timed out", "interrupted", "flaky".
const char* toString(TestStatus status);
// The same word as the text report's per-test lines show it: the failing ones in capitals
// ("FAILED", "TIMED OUT"). Both come from one table, in TestStatus.cpp.
const char* toLabel(TestStatus status);

// True for the states that make a run fail (everything but passed, skipped and flaky).
inline bool isFailure(TestStatus status) {
    return status != TestStatus::Passed && status != TestStatus::Skipped &&
           status != TestStatus::Flaky;
}

}  // namespace robottestingframework
