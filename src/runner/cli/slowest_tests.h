// --durations N, as pytest has it: the N slowest tests of the run (0: all), slowest first,
// printed after the run.
#pragma once

#include <string>

#include <robottestingframework/TestResultCollector.h>

namespace robottestingframework {
namespace runner {

// "slowest 3 of 7 tests:" (or "the 7 tests, slowest first:" for 0), then one line per test: its
// time (all its repetitions and attempts), its state and its id. Tests that did not run
// (skipped) are left out. Empty when no test ran.
std::string slowestTestsText(const TestResultCollector& collector, int count);

}  // namespace runner
}  // namespace robottestingframework
