// The runner's exit statuses (SPEC 3.1) and the one a run ends with.
#pragma once

#include <robottestingframework/TestResultCollector.h>

namespace robottestingframework {
namespace runner {

constexpr int allPassed = 0;
constexpr int somethingFailed = 1;
constexpr int configurationError = 2;
// No test selected (unless --allow-empty): pytest's code for "no tests collected".
constexpr int nothingSelected = 5;
// --world-down of a world that never started (its --world-up failed and said why): nothing to
// stop. The automake convention for "skipped", which robottestingframework_discover_tests gives
// CTest as the world:down test's SKIP_RETURN_CODE: the world's failure is counted once.
constexpr int worldNeverStarted = 77;

// Interrupted: 128 + the signal, as shells report it (130 for Ctrl-C, 143 for SIGTERM).
constexpr int interruptedBy(int signal) {
    return 128 + signal;
}

// A test failed, or a suite did (its fixture, or a test in it).
bool anythingFailed(const TestResultCollector& collector);

// The status of a run: interrupted (`signal` not 0), else somethingFailed when anything failed
// or, with --fail-on-flaky, a test was flaky, else allPassed.
int runStatus(const TestResultCollector& collector, bool failOnFlaky, int signal);

}  // namespace runner
}  // namespace robottestingframework
