#include "runner/plan/shard_of_this_machine.h"

#include <cstdlib>

namespace robottestingframework {
namespace runner {

namespace {

// One CI engine's pair of variables. `oneBased`: GitLab counts its jobs from 1.
struct Convention {
    const char* engine;
    const char* index;
    const char* count;
    bool oneBased;
};

const Convention conventions[] = {
    {"Bazel", "TEST_SHARD_INDEX", "TEST_TOTAL_SHARDS", false},
    {"GoogleTest", "GTEST_SHARD_INDEX", "GTEST_TOTAL_SHARDS", false},
    {"GitLab CI", "CI_NODE_INDEX", "CI_NODE_TOTAL", true},
    {"Kubernetes Indexed Job", "JOB_COMPLETION_INDEX", "RTF_SHARD_COUNT", false},
};

// A whole number in decimal digits only (no sign, no spaces), at most maxShards.
bool parseWhole(const std::string& text, unsigned long& value) {
    if (text.empty() || text.size() > 9 ||
        text.find_first_not_of("0123456789") != std::string::npos) {
        return false;
    }
    value = std::strtoul(text.c_str(), nullptr, 10);
    return value <= maxShards;
}

// Checks one index/count pair; `indexName`/`countName` are what the user wrote (flag or variable).
bool checkPair(const std::string& indexText, const std::string& countText,
               const std::string& indexName, const std::string& countName, bool oneBased,
               ShardChoice& choice, std::string& error) {
    unsigned long count = 0;
    unsigned long index = 0;
    if (!parseWhole(countText, count) || count == 0) {
        error = countName + " '" + countText + "': expected a whole number of shards from 1 to " +
                std::to_string(maxShards);
        return false;
    }
    const unsigned long lowest = oneBased ? 1 : 0;
    if (!parseWhole(indexText, index) || index < lowest || index - lowest >= count) {
        error = indexName + " '" + indexText + "': expected a whole number from " +
                std::to_string(lowest) + " to " + std::to_string(count - 1 + lowest) + " (" +
                countName + " is " + std::to_string(count) + ")";
        return false;
    }
    choice.sharded = true;
    choice.index = static_cast<unsigned int>(index - lowest);
    choice.count = static_cast<unsigned int>(count);
    return true;
}

}  // namespace

bool chooseShard(const ShardFlags& flags, const EnvironmentLookup& environment, ShardChoice& choice,
                 std::string& error) {
    choice = ShardChoice();
    if (!flags.index.empty() || !flags.count.empty()) {
        if (flags.index.empty() || flags.count.empty()) {
            error = flags.index.empty() ? "--shard-count needs --shard-index"
                                        : "--shard-index needs --shard-count";
            return false;
        }
        if (!checkPair(flags.index, flags.count, "--shard-index", "--shard-count", false, choice,
                       error)) {
            return false;
        }
        choice.source = "--shard-index " + flags.index + " --shard-count " + flags.count;
        return true;
    }
    ShardChoice found;
    std::string foundNames;
    for (const Convention& convention : conventions) {
        const char* index = environment(convention.index);
        const char* count = environment(convention.count);
        // GitLab sets CI_NODE_TOTAL=1 in every job that is not parallel; Kubernetes sets
        // JOB_COMPLETION_INDEX in every Indexed Job, sharded by this runner or not.
        if (convention.oneBased && index == nullptr && count != nullptr &&
            std::string(count) == "1") {
            continue;
        }
        if (std::string(convention.count) == "RTF_SHARD_COUNT" && count == nullptr) {
            continue;
        }
        if (index == nullptr && count == nullptr) {
            continue;
        }
        if (index == nullptr || count == nullptr) {
            error = std::string(index == nullptr ? convention.count : convention.index) +
                    " is set but " + (index == nullptr ? convention.index : convention.count) +
                    " is not (" + convention.engine + " sets both)";
            return false;
        }
        ShardChoice candidate;
        if (!checkPair(index, count, convention.index, convention.count, convention.oneBased,
                       candidate, error)) {
            return false;
        }
        const std::string names = std::string(convention.engine) + " " + convention.index + "=" +
                                  index + " " + convention.count + "=" + count;
        if (found.sharded && (found.index != candidate.index || found.count != candidate.count)) {
            error = "conflicting shard variables: " + foundNames + " (shard " +
                    std::to_string(found.index) + " of " + std::to_string(found.count) + ") but " +
                    names + " (shard " + std::to_string(candidate.index) + " of " +
                    std::to_string(candidate.count) +
                    "); unset one or give --shard-index and "
                    "--shard-count";
            return false;
        }
        if (!found.sharded) {
            found = candidate;
            foundNames = names;
        }
    }
    if (found.sharded) {
        choice = found;
        choice.source = foundNames;
    }
    return true;
}

const std::vector<std::string>& shardVariables() {
    static const std::vector<std::string> names = {
        "TEST_SHARD_INDEX",     "TEST_TOTAL_SHARDS",  "TEST_SHARD_STATUS_FILE", "XML_OUTPUT_FILE",
        "GTEST_SHARD_INDEX",    "GTEST_TOTAL_SHARDS", "CI_NODE_INDEX",          "CI_NODE_TOTAL",
        "JOB_COMPLETION_INDEX", "RTF_SHARD_COUNT"};
    return names;
}

}  // namespace runner
}  // namespace robottestingframework
