// The planning stage of a run: the suites read, cut down to the tests an earlier report says
// failed (--rerun-failed), then to the selection (--tag, --exclude-tag, --filter), then to this
// machine's shard. It prints nothing and runs nothing, so how the three combine is tested
// without a run; main says its notes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "reporters/reporter.h"
#include "runner/cli/options.h"
#include "runner/cli/suite_durations.h"
#include "runner/model/suite_model.h"
#include "runner/plan/shard_of_this_machine.h"

namespace robottestingframework {
namespace runner {

// A line for the console, without the program's name.
struct PlanNote {
    enum class Stream { Out, Err };  // Out: what the run is; Err: a warning
    Stream stream = Stream::Out;
    std::string text;
};

struct PlannedRun {
    enum class Outcome {
        Run,             // run (or list) `suites`
        NothingToRerun,  // the --rerun-failed report has no failed test: a success
        Error,           // a configuration error, `error` says which
        // The selection (--filter, --tag, --exclude-tag) leaves no test of suites that have
        // some: an error of its own (exit 5, as pytest's), unless --allow-empty. Never said for
        // a shard, nor for suites written without tests (RTF 2.x runs them: exit 0).
        NothingSelected,
    };
    Outcome outcome = Outcome::Run;
    std::string error;
    // Said in this order, whatever the outcome.
    std::vector<PlanNote> notes;
    // This shard's suites, in the selection's order; when listing (--list, --list-vars), every
    // shard's, the list showing each one's shard.
    std::vector<SuiteSpec> suites;
    ShardChoice shard;  // the shard this run is; a rerun takes none
    // Each suite's time from --durations-from, read once for the shards and the progress line's
    // ETA; none without --durations-from or, when not sharded, when it cannot be read (a warning
    // says so).
    std::optional<SuiteSeconds> durations;
    // When listing a sharded run: the shard of each of `suites`; else empty.
    std::vector<unsigned int> shardOf;
    // What the outputs say of the run's place: a rerun (of which shard), this shard, and each
    // suite's place among every selected suite.
    reporters::ReporterSettings reportSettings;
};

// Plans the run of `suites` (as read, in order) for `shard` (prepareShard's choice). Reads the
// --rerun-failed and --durations-from reports; a report that cannot be read is an Error.
PlannedRun planRun(const Options& options, std::vector<SuiteSpec> suites, ShardChoice shard);

}  // namespace runner
}  // namespace robottestingframework
