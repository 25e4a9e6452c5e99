// --shard-index/--shard-count: which suites of the selection one machine of N runs. A pure
// function of its inputs, so every machine computes the same split.
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {
namespace runner {

// One selected suite as the split sees it.
struct ShardItem {
    std::string id;                  // sorts the suites: the same on every machine
    std::vector<std::string> locks;  // suites sharing a lock go to the same shard
    long long milliseconds = -1;     // from --durations-from; -1: unknown (the known ones' mean)
};

// The shard (0 to count - 1) of each item, in the items' order; every item is in exactly one.
// Suites that share a lock form one group. Without durations (`balance` false) the groups go
// round-robin in the order of their smallest id; with them, longest first onto the least
// loaded shard (ties: the smaller id, the lower shard). Equal ids keep their input order.
std::vector<unsigned int> assignShards(const std::vector<ShardItem>& items, unsigned int count,
                                       bool balance);

}  // namespace runner
}  // namespace robottestingframework
