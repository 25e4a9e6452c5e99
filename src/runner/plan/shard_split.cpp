#include "runner/plan/shard_split.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace robottestingframework {
namespace runner {

namespace {

// Union-find over the items: one set per group of suites linked by shared locks.
std::size_t rootOf(std::vector<std::size_t>& parent, std::size_t item) {
    while (parent[item] != item) {
        parent[item] = parent[parent[item]];
        item = parent[item];
    }
    return item;
}

struct Group {
    std::size_t first = 0;  // its smallest item in the sorted order
    long long milliseconds = 0;
    std::vector<std::size_t> items;
};

}  // namespace

std::vector<unsigned int> assignShards(const std::vector<ShardItem>& items, unsigned int count,
                                       bool balance) {
    std::vector<unsigned int> shards(items.size(), 0);
    if (items.empty() || count <= 1) {
        return shards;
    }
    // The sorted order: by id, equal ids in input order.
    std::vector<std::size_t> order(items.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return items[a].id < items[b].id; });

    std::vector<std::size_t> parent(items.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::map<std::string, std::size_t> holder;  // lock -> an item that names it
    for (std::size_t i = 0; i < items.size(); ++i) {
        for (const auto& lock : items[i].locks) {
            auto found = holder.emplace(lock, i);
            if (!found.second) {
                parent[rootOf(parent, i)] = rootOf(parent, found.first->second);
            }
        }
    }

    // Unknown durations count as the mean of the known ones (whole milliseconds, so every
    // machine adds up the same).
    long long known = 0;
    long long total = 0;
    for (const auto& item : items) {
        if (item.milliseconds >= 0) {
            ++known;
            total += item.milliseconds;
        }
    }
    const long long mean = known > 0 ? total / known : 1;

    std::map<std::size_t, Group> byRoot;
    for (std::size_t place = 0; place < order.size(); ++place) {
        const std::size_t item = order[place];
        Group& group = byRoot[rootOf(parent, item)];
        if (group.items.empty()) {
            group.first = place;
        }
        group.items.push_back(item);
        group.milliseconds += items[item].milliseconds >= 0 ? items[item].milliseconds : mean;
    }
    std::vector<Group> groups;
    for (auto& entry : byRoot) {
        groups.push_back(std::move(entry.second));
    }
    std::sort(groups.begin(), groups.end(),
              [](const Group& a, const Group& b) { return a.first < b.first; });

    if (!balance) {
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (std::size_t item : groups[g].items) {
                shards[item] = static_cast<unsigned int>(g % count);
            }
        }
        return shards;
    }
    std::stable_sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) {
        return a.milliseconds > b.milliseconds;
    });
    std::vector<long long> load(count, 0);
    for (const Group& group : groups) {
        const auto least = std::min_element(load.begin(), load.end()) - load.begin();
        load[least] += group.milliseconds;
        for (std::size_t item : group.items) {
            shards[item] = static_cast<unsigned int>(least);
        }
    }
    return shards;
}

}  // namespace runner
}  // namespace robottestingframework
