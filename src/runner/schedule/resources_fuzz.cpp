// Fuzz target: a --resources file through parseResourceFile, then what the scheduler does with
// the pools it gives (cmake/Fuzz.cmake, ./run.sh fuzz): checkPools for suites asking for
// items, and every suite taking and releasing what it asked for. Every error names the file;
// items are never given out beyond their slots.
#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "runner/schedule/resources.h"

using namespace robottestingframework;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    runner::ResourcePools pools;
    try {
        pools = runner::parseResourceFile(text, "resources.json");
    } catch (const std::runtime_error& e) {
        if (std::string(e.what()).rfind("resources.json: ", 0) != 0) {
            __builtin_trap();  // every error names the file
        }
        return 0;
    }
    // Two suites per pool of the file, asking for one and for two items, and a lock.
    std::vector<runner::SuiteSpec> suites;
    for (const auto& pool : pools.pools) {
        for (unsigned int count : {1u, 2u}) {
            runner::SuiteSpec suite;
            suite.name = pool.first + std::to_string(count);
            suite.where = {"suite.xml", count};
            runner::ResourceSpec wanted;
            wanted.pool = pool.first;
            wanted.count = count;
            wanted.where = suite.where;
            suite.resources.push_back(wanted);
            runner::ResourceSpec lock;
            lock.lock = "robot:arm";
            suite.resources.push_back(lock);
            suites.push_back(suite);
        }
    }
    const std::string problem = runner::checkPools(suites, pools);
    if (!problem.empty() && problem.rfind("suite.xml:", 0) != 0) {
        __builtin_trap();  // a problem names the suite file and line
    }
    if (!problem.empty()) {
        return 0;
    }
    runner::ResourceTable table(pools);
    std::map<std::string, std::map<std::string, unsigned int>> given;  // pool -> item -> holders
    std::vector<runner::ResourceTable::Held> held;
    for (const auto& suite : suites) {
        runner::ResourceTable::Held taken;
        std::string busyLock;
        std::string busyPool;
        if (table.take(suite, suite.name, taken, busyLock, busyPool)) {
            for (const auto& pool : taken.items) {
                for (const auto& id : pool.second) {
                    ++given[pool.first][id];
                }
            }
            held.push_back(taken);
        }
    }
    for (const auto& pool : given) {
        for (const auto& item : pool.second) {
            unsigned int slots = 0;
            for (const auto& known : pools.pools[pool.first]) {
                if (known.id == item.first) {
                    slots = known.slots;
                }
            }
            if (item.second > slots) {
                __builtin_trap();  // an item given to more suites than it has slots
            }
        }
    }
    for (const auto& taken : held) {
        table.release(taken);
    }
    // Everything free again: the first suite takes what it asks for at once.
    runner::ResourceTable::Held again;
    std::string busyLock;
    std::string busyPool;
    if (!suites.empty() && !table.take(suites[0], suites[0].name, again, busyLock, busyPool)) {
        __builtin_trap();
    }
    return 0;
}
