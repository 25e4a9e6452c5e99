// A sharded run, before it starts: the shard chosen from the flags and the CI engine's variables,
// Bazel's conventions applied, the variables taken out of the tests' environment, and the
// selected suites cut down to the shard's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "runner/cli/options.h"
#include "runner/cli/suite_durations.h"
#include "runner/model/suite_model.h"
#include "runner/plan/shard_of_this_machine.h"

namespace robottestingframework {
namespace runner {

// Chooses the shard (shard_of_this_machine.h) from the flags and this process's environment; then,
// for Bazel, adds a JUnit output to $XML_OUTPUT_FILE (even with --no-output), points TMPDIR at
// $TEST_TMPDIR and touches $TEST_SHARD_STATUS_FILE; and removes every shard variable
// (shardVariables()) from the environment, so no test, in any isolation mode, sees them. False with
// `error` on bad input.
bool prepareShard(Options& options, ShardChoice& choice, std::string& error);

// The shard of each of `suites` (shard_split.h): by sorted id, suites sharing a lock together (and
// suites linked by a test's `depends` on a test of another), and balanced by the suites' earlier
// times (--durations-from) when there are any.
std::vector<unsigned int> shardsOf(const std::vector<SuiteSpec>& suites, unsigned int count,
                                   const std::optional<SuiteSeconds>& durations);

// What makes the shards' reports recognisably those of one run: the whole selection (each
// suite's name, file name and test ids, in order) and the shard count, hashed (FNV-1a, 64 bits,
// as 16 hex digits: the same on every machine and platform, wherever the sources are checked
// out). Each shard report carries it; --merge refuses a report whose plan differs.
std::string planIdentity(const std::vector<SuiteSpec>& suites, unsigned int count);

}  // namespace runner
}  // namespace robottestingframework
