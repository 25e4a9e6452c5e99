// The split of suites between shards (shard_split.h): deterministic, complete, locks together,
// balanced by durations.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "runner/plan/shard_split.h"

using namespace robottestingframework::runner;

namespace {

std::vector<ShardItem> named(std::initializer_list<const char*> ids) {
    std::vector<ShardItem> items;
    for (const char* id : ids) {
        ShardItem item;
        item.id = id;
        items.push_back(item);
    }
    return items;
}

}  // namespace

TEST(Shards, RoundRobinOverSortedIds) {
    // Given in any order, split by sorted id: a b c d e -> 0 1 2 0 1.
    const auto items = named({"e", "c", "a", "d", "b"});
    EXPECT_EQ(assignShards(items, 3, false), (std::vector<unsigned int>{1, 2, 0, 0, 1}));
}

TEST(Shards, SameInputsGiveTheSameSplitWhateverTheOrder) {
    auto forward = named({"s1", "s2", "s3", "s4", "s5", "s6", "s7"});
    auto backward = forward;
    std::reverse(backward.begin(), backward.end());
    const auto a = assignShards(forward, 3, false);
    const auto b = assignShards(backward, 3, false);
    for (std::size_t i = 0; i < forward.size(); ++i) {
        EXPECT_EQ(a[i], b[forward.size() - 1 - i]) << forward[i].id;
    }
}

TEST(Shards, EverySuiteIsInExactlyOneShardInRange) {
    std::vector<ShardItem> items;
    for (int i = 0; i < 100; ++i) {
        ShardItem item;
        item.id = "suite" + std::to_string(i);
        item.milliseconds = (i * 37) % 11 * 100;
        items.push_back(item);
    }
    for (bool balance : {false, true}) {
        for (unsigned int count : {1u, 2u, 7u, 150u}) {
            const auto shards = assignShards(items, count, balance);
            ASSERT_EQ(shards.size(), items.size());
            for (unsigned int shard : shards) {
                EXPECT_LT(shard, count);
            }
        }
    }
}

TEST(Shards, MoreShardsThanSuitesLeavesTheLastOnesEmpty) {
    const auto shards = assignShards(named({"a", "b"}), 4, false);
    EXPECT_EQ(shards, (std::vector<unsigned int>{0, 1}));
}

TEST(Shards, SuitesSharingALockGoTogether) {
    auto items = named({"a", "b", "c", "d", "e", "f"});
    items[0].locks = {"robot:left-arm"};
    items[3].locks = {"robot:left-arm", "camera"};
    items[5].locks = {"camera"};  // through d, with a too
    for (bool balance : {false, true}) {
        const auto shards = assignShards(items, 3, balance);
        EXPECT_EQ(shards[0], shards[3]);
        EXPECT_EQ(shards[3], shards[5]);
        // The three others are spread over the shards, the group counting once.
        std::set<unsigned int> used(shards.begin(), shards.end());
        EXPECT_EQ(used.size(), 3u);
    }
}

TEST(Shards, DurationsPutTheLongestFirstOntoTheLeastLoaded) {
    auto items = named({"a", "b", "c", "d"});
    items[0].milliseconds = 9000;  // alone on one shard
    items[1].milliseconds = 3000;
    items[2].milliseconds = 3000;
    items[3].milliseconds = 3000;
    const auto shards = assignShards(items, 2, true);
    EXPECT_EQ(shards, (std::vector<unsigned int>{0, 1, 1, 1}));
}

TEST(Shards, UnknownSuitesWeighTheMeanOfTheKnownOnes) {
    auto items = named({"a", "b", "c"});
    items[0].milliseconds = 1000;
    items[1].milliseconds = 3000;  // mean 2000: c goes after b, onto a's shard (1000 < 3000)
    const auto shards = assignShards(items, 2, true);
    EXPECT_EQ(shards, (std::vector<unsigned int>{1, 0, 1}));
}

TEST(Shards, WithoutDurationsTimesAreIgnored) {
    auto items = named({"a", "b", "c", "d"});
    items[0].milliseconds = 9000;
    EXPECT_EQ(assignShards(items, 2, false), (std::vector<unsigned int>{0, 1, 0, 1}));
}
