// What a worker process does once forked: load exactly one test (or fixture) and run it,
// sending its events on `channel`. Its stdout and stderr are already the runner's pipe.
#pragma once

#include "isolation/wire_format.h"

namespace robottestingframework {
namespace isolation {

// Runs the test of `request`, then returns the process's exit code (0: it ran to the end,
// whatever its outcome; the runner reads the outcome from the events).
int runTestWorker(const WorkRequest& request, int channel);

// Loads the fixture of `request`, then serves the runner's calls (setup, check, tearDown)
// read from `channel` until the runner closes it.
int runFixtureWorker(const WorkRequest& request, int channel);

}  // namespace isolation
}  // namespace robottestingframework
