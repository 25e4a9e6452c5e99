// Which shard this machine runs: --shard-index/--shard-count, else the variables a CI engine
// sets (Bazel, GoogleTest, GitLab parallel:, Kubernetes Indexed Jobs). A pure function of the
// flags and the environment, so it is tested without setting either.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace robottestingframework {
namespace runner {

// The most shards: far more machines than a run spreads over, small enough to list.
constexpr unsigned long maxShards = 100000UL;

struct ShardChoice {
    bool sharded = false;  // false: run every selected suite
    unsigned int index = 0;
    unsigned int count = 1;
    std::string source;  // what said so, for the console: "--shard-index 1 --shard-count 4"
};

// The flags as given; empty when not.
struct ShardFlags {
    std::string index;
    std::string count;
};

// Reads an environment variable; nullptr when it is not set.
using EnvironmentLookup = std::function<const char*(const char*)>;

// Chooses the shard. Explicit flags win over the environment; conventions that are all set
// must agree. False with `error` naming the flag or variable when a value is not a whole
// number, the index is not below the count, a pair is incomplete, or two conventions disagree.
bool chooseShard(const ShardFlags& flags, const EnvironmentLookup& environment, ShardChoice& choice,
                 std::string& error);

// Every variable chooseShard reads, and Bazel's TEST_SHARD_STATUS_FILE and XML_OUTPUT_FILE:
// taken out of the tests' environment, so a GoogleTest-based test does not shard itself again
// (nor writes its XML over the runner's).
const std::vector<std::string>& shardVariables();

}  // namespace runner
}  // namespace robottestingframework
