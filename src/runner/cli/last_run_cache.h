// The cache folder (.rtf_cache in the working folder, --cache-dir DIR, --no-cache), as pytest's
// .pytest_cache: it keeps the ids of the tests that failed, errored, crashed or timed out, for
// --lf and --ff. The folder has its own .gitignore ("*") and a README.md saying what it is.
//
// As pytest's lastfailed: after a run, the tests it ran that failed are added and the ones it
// ran that did not fail are taken out; the failures of tests this run did not run (another
// selection, another shard run before in the same folder) stay. The file is written whole to a
// temporary file and renamed over the old one, so a reader never sees half of it; of processes
// that write it at the same moment (shards run side by side in one folder, ctest -j), the last
// one wins. It is written only after a run with a failure, or when the folder exists already (to
// clear the failures): a run that passes leaves no folder behind. --list never writes it.
#pragma once

#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <robottestingframework/TestResultCollector.h>

#include "runner/cli/options.h"

namespace robottestingframework {
namespace runner {

// The file inside the cache folder: one test id a line.
extern const char* const lastFailedFileName;

// The ids of the last run's failures in the cache folder `folder`; none when it has none. False
// with `error` when the file exists but cannot be read.
bool readLastFailed(const std::string& folder, std::set<std::string>& ids, std::string& error);

// The failures to keep after a run: `previous` less the tests of `results` (id, state as
// TestStatus says it) that did not fail, plus the ones that did. An interrupted test keeps what
// it was.
std::set<std::string> updatedLastFailed(
    const std::set<std::string>& previous,
    const std::vector<std::pair<std::string, std::string>>& results);

// Writes `ids` into the cache folder `folder` (made, with its .gitignore and README.md, when
// missing), atomically. False with `error` (naming the file) when it cannot.
bool writeLastFailed(const std::string& folder, const std::set<std::string>& ids,
                     std::string& error);

// After a run: the cache folder of `options` updated with the run's outcome (unless --no-cache);
// a cache that cannot be written is a warning on `console`, the exit status stays the run's.
void recordLastRun(const Options& options, const TestResultCollector& collector,
                   std::FILE* console);

}  // namespace runner
}  // namespace robottestingframework
