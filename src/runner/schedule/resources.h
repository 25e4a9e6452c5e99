// Resources suites share: locks (by name, one holder at a time) and pools of items given by
// --resources FILE, a JSON file shaped like CTest's resource spec file:
//   {"version": {"major": 1, "minor": 0},
//    "local": [{"ros_domain": [{"id": "1"}, {"id": "2", "slots": 2}]}]}
// An item with `slots` N may be held by N suites at once (default 1). A pool no such file gives
// takes its items from the suites' <resource pool="NAME" default="ID ..."/>, so a suite file
// runs as written.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

struct PoolItem {
    std::string id;
    unsigned int slots = 1;
};

struct ResourcePools {
    std::string file;  // where they were read, for messages; empty: no --resources
    std::map<std::string, std::vector<PoolItem>> pools;
    std::map<std::string, std::string> origin;  // pool -> where its items come from (messages)
};

// Reads --resources FILE; throws std::runtime_error "FILE: what is wrong" when it cannot.
ResourcePools readResourceFile(const std::string& path);
// The same from the file's text; `path` names it in messages.
ResourcePools parseResourceFile(const std::string& text, const std::string& path);

// Gives each pool that `pools` lacks the items of its suites' default="..." (a --resources
// file wins over the suite). Empty, or "suite.xml:4: ..." when two suites give one pool
// different defaults.
std::string addSuiteDefaults(const std::vector<SuiteSpec>& suites, ResourcePools& pools);

// Empty when every <resource pool="..."> of `suites` names a pool of `pools` that has enough
// items; else "suite.xml:4: ..." saying which pool and what is wrong.
std::string checkPools(const std::vector<SuiteSpec>& suites, const ResourcePools& pools);

// RTF_RESOURCE_<POOL>: the pool's name in capitals, anything but letters and digits as _.
std::string resourceVariable(const std::string& pool);

// Who holds what while the scheduler runs suites (one thread: the scheduler's).
class ResourceTable {
public:
    explicit ResourceTable(const ResourcePools& pools);

    // What a suite took: its locks and, per pool, the ids of its items.
    struct Held {
        std::vector<std::string> locks;
        std::map<std::string, std::vector<std::string>> items;
    };

    // Takes every lock and item `suite` needs, all or nothing; the locks in sorted order.
    // False when one is held: `busyLock` names the first lock held by another suite (empty
    // when it is a pool that has no free item).
    bool take(const SuiteSpec& suite, const std::string& holder, Held& held, std::string& busyLock,
              std::string& busyPool);
    void release(const Held& held);
    // The suite that holds `lock`; empty when free.
    std::string holderOf(const std::string& lock) const;

private:
    std::map<std::string, std::vector<PoolItem>> pools_;
    std::map<std::string, std::vector<unsigned int>> used_;  // per pool, per item
    std::map<std::string, std::string> locks_;               // lock -> holder
};

}  // namespace runner
}  // namespace robottestingframework
