// A run's records (the collector's, once the run is over) added to the history: each suite's
// time and each test's id, state, time and attempts.
#pragma once

#include <robottestingframework/TestResultCollector.h>

#include "runner/history/run_appender.h"

namespace robottestingframework {
namespace runner {

// The id the history keys a test by: "SUITE/TEST", as every report names it.
std::string historyTestId(const SuiteRecord& suite, const TestRecord& test);

void appendCollectedRun(RunAppender& appender, const TestResultCollector& collector);

}  // namespace runner
}  // namespace robottestingframework
