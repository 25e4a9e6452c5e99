// --watch (docs/how-to/watch.md): the runner runs the tests in a child runner (its own command line
// without --watch), then waits for a suite file, a test file or a plug-in of the run to change,
// and runs them again, the tests that failed first (a run of them alone, then the whole run when
// they pass). Ctrl-C stops the run under way as it always does, and the watch with it; the
// status is the last run's. Linux watches with inotify, other POSIX systems poll, Windows says
// it is not supported (exit 2).
#pragma once

#include "runner/cli/options.h"
#include "runner/model/suite_model.h"

#include <string>
#include <vector>

namespace robottestingframework {
namespace runner {

// The files a run depends on: its suite files, test files, plug-ins and fixtures, each once.
std::vector<std::string> watchedFiles(const std::vector<SuiteSpec>& suites);

// The child's command line: `argv` without --watch, with `report` (a JUnit file) added to its
// outputs; a run that names none also keeps its default result.txt.
std::vector<std::string> watchedRunArguments(int argc, char** argv, const std::string& report);

// Runs and watches until Ctrl-C; returns the last run's status (2 when watching is not
// possible).
int watchCommand(int argc, char** argv, Options& options);

}  // namespace runner
}  // namespace robottestingframework
