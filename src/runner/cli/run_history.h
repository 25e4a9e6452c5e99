// This run's part of --history FILE: the file is checked before anything runs (a damaged or
// foreign file is an error naming it); once the run is over the run is appended and each
// test's last 30 runs are read back for the reports. A history that cannot be written is a
// warning: the reports are still written and the exit status stays the run's.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <robottestingframework/TestResultCollector.h>

#include "reporters/history_strip.h"
#include "runner/cli/options.h"
#include "runner/cli/planned_run.h"
#include "runner/history/history_run.h"

namespace robottestingframework {
namespace runner {

class RunHistory {
public:
    // How many runs the pages show per test.
    static constexpr unsigned int shownRuns = 30;

    // Throws HistoryError when `path` exists and is not a history file this runner reads.
    RunHistory(std::string path, HistoryRun run);

    // Each test's last runs before this one (for the live page, before the run starts); none
    // when the file has no run yet.
    reporters::HistoryStrips earlierStrips() const;

    // Filled by record(): what the reports show (share it through ReporterSettings::history).
    std::shared_ptr<const reporters::HistoryStrips> strips() const { return strips_; }

    // Appends the run and, when `readBack` (an output shows them), reads the strips back; false
    // (after a warning on `console`) when the history could not be written or read.
    bool record(const TestResultCollector& collector, std::FILE* console, bool readBack);

private:
    std::string path_;
    HistoryRun run_;
    std::shared_ptr<reporters::HistoryStrips> strips_;
};

// The run as the history keeps it: its key (the CI engine's run), now, this host, the command
// line, the shard.
HistoryRun thisRun(int argc, const char* const* argv, bool sharded, unsigned int shardIndex,
                   unsigned int shardCount);

// --history FILE: the run's history, checked before anything runs (the reports' settings get
// its strips); none without --history. False, having said why, when the file is not a history.
bool openRunHistory(const Options& options, PlannedRun& planned, int argc, const char* const* argv,
                    std::unique_ptr<RunHistory>& history);

}  // namespace runner
}  // namespace robottestingframework
