#include "runner/schedule/resources.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "platform/bounded_file.h"

namespace robottestingframework {
namespace runner {

namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw std::runtime_error(path + ": " + what);
}

// CTest's rule for resource type and id names: lower-case letters, digits and _, a type not
// starting with a digit. We also take upper-case letters, '-' and '.' in ids.
bool isPoolName(const std::string& name) {
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) {
        return false;
    }
    return std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
}

}  // namespace

ResourcePools readResourceFile(const std::string& path) {
    // A resource file is a few lines of JSON: 16 MiB is far beyond any.
    std::string text;
    std::string error;
    if (!platform::readBoundedFile(path, "resource file", 16 * 1024 * 1024, platform::Pipes::Read,
                                   text, error)) {
        throw std::runtime_error(error);
    }
    return parseResourceFile(text, path);
}

ResourcePools parseResourceFile(const std::string& text, const std::string& path) {
    json document;
    try {
        document = json::parse(text);
    } catch (const json::exception& e) {
        // parse_error, or out_of_range for a number too large for a double.
        fail(path, std::string("not valid JSON: ") + e.what());
    }
    const std::string shape =
        " (expected {\"version\": {\"major\": 1, \"minor\": 0}, \"local\": [{\"POOL\": "
        "[{\"id\": \"ITEM\", \"slots\": 1}, ...]}]})";
    if (!document.is_object() || !document.contains("version") || !document.contains("local")) {
        fail(path, "not a resource spec file" + shape);
    }
    const json& version = document["version"];
    if (!version.is_object() || !version.contains("major") || version["major"] != 1) {
        fail(path, "\"version\" must be {\"major\": 1, \"minor\": 0}" + shape);
    }
    const json& local = document["local"];
    if (!local.is_array() || local.size() != 1 || !local[0].is_object()) {
        fail(path, "\"local\" must be an array of one object" + shape);
    }
    ResourcePools pools;
    pools.file = path;
    for (const auto& pool : local[0].items()) {
        const std::string name = pool.key();
        if (!isPoolName(name)) {
            fail(path, "pool \"" + name +
                           "\": a pool name is letters, digits and _, not starting with a digit");
        }
        if (!pool.value().is_array()) {
            fail(path, "pool \"" + name + "\" must be an array of items" + shape);
        }
        std::set<std::string> ids;
        std::vector<PoolItem>& items = pools.pools[name];
        for (const json& item : pool.value()) {
            if (!item.is_object() || !item.contains("id") || !item["id"].is_string()) {
                fail(path, "pool \"" + name + "\": each item is {\"id\": \"...\"}" + shape);
            }
            PoolItem parsed;
            parsed.id = item["id"].get<std::string>();
            if (!isPoolItemId(parsed.id)) {
                fail(path, "pool \"" + name + "\": item id \"" + parsed.id +
                               "\" is not letters, digits, _, - and .");
            }
            if (!ids.insert(parsed.id).second) {
                fail(path, "pool \"" + name + "\": item id \"" + parsed.id + "\" given twice");
            }
            if (item.contains("slots")) {
                const json& slots = item["slots"];
                if (!slots.is_number_integer() || slots.get<long long>() < 1 ||
                    slots.get<long long>() > 1000000) {
                    fail(path, "pool \"" + name + "\", item \"" + parsed.id +
                                   "\": \"slots\" must be a whole number from 1 to 1000000");
                }
                parsed.slots = slots.get<unsigned int>();
            }
            items.push_back(parsed);
        }
    }
    return pools;
}

std::string addSuiteDefaults(const std::vector<SuiteSpec>& suites, ResourcePools& pools) {
    std::map<std::string, const ResourceSpec*> firstDefault;  // pool -> the suite that gave it
    for (const auto& suite : suites) {
        for (const auto& resource : suite.resources) {
            if (resource.pool.empty() || resource.defaults.empty() ||
                (pools.pools.count(resource.pool) != 0 && firstDefault.count(resource.pool) == 0)) {
                continue;
            }
            auto given = firstDefault.find(resource.pool);
            if (given != firstDefault.end()) {
                if (given->second->defaults != resource.defaults) {
                    return resource.where.toString() + ": pool \"" + resource.pool +
                           "\" has another default at " + given->second->where.toString() +
                           "; give one default, or the pool in a --resources file";
                }
                continue;
            }
            firstDefault[resource.pool] = &resource;
            std::vector<PoolItem>& items = pools.pools[resource.pool];
            for (const auto& id : resource.defaults) {
                items.push_back(PoolItem{id, 1});
            }
            pools.origin[resource.pool] = "default= at " + resource.where.toString();
        }
    }
    return {};
}

std::string checkPools(const std::vector<SuiteSpec>& suites, const ResourcePools& pools) {
    for (const auto& suite : suites) {
        for (const auto& resource : suite.resources) {
            if (resource.pool.empty()) {
                continue;
            }
            auto found = pools.pools.find(resource.pool);
            if (found == pools.pools.end()) {
                std::string known;
                for (const auto& pool : pools.pools) {
                    known += (known.empty() ? "" : ", ") + pool.first;
                }
                return resource.where.toString() + ": pool \"" + resource.pool +
                       "\" does not exist" +
                       (pools.file.empty() ? std::string(" (no --resources FILE gives pools; "
                                                         "a suite can give default=\"ID ...\")")
                                           : " in " + pools.file +
                                                 (known.empty() ? " (it has no pool)"
                                                                : " (it has " + known + ")"));
            }
            if (resource.count > found->second.size()) {
                auto origin = pools.origin.find(resource.pool);
                return resource.where.toString() + ": pool \"" + resource.pool + "\" (" +
                       (origin != pools.origin.end() ? origin->second : pools.file) + ") has " +
                       std::to_string(found->second.size()) + " item(s); suite \"" + suite.name +
                       "\" takes " + std::to_string(resource.count) + " and could never run";
            }
        }
    }
    return {};
}

std::string resourceVariable(const std::string& pool) {
    std::string name = "RTF_RESOURCE_";
    for (char c : pool) {
        name += std::isalnum(static_cast<unsigned char>(c))
                    ? static_cast<char>(std::toupper(static_cast<unsigned char>(c)))
                    : '_';
    }
    return name;
}

ResourceTable::ResourceTable(const ResourcePools& pools) : pools_(pools.pools) {
    for (const auto& pool : pools_) {
        used_[pool.first].assign(pool.second.size(), 0);
    }
}

bool ResourceTable::take(const SuiteSpec& suite, const std::string& holder, Held& held,
                         std::string& busyLock, std::string& busyPool) {
    busyLock.clear();
    busyPool.clear();
    std::set<std::string> locks;  // sorted, each once
    std::map<std::string, unsigned int> wanted;
    for (const auto& resource : suite.resources) {
        if (!resource.lock.empty()) {
            locks.insert(resource.lock);
        } else {
            wanted[resource.pool] += resource.count;
        }
    }
    for (const auto& lock : locks) {
        if (locks_.count(lock) != 0) {
            busyLock = lock;
            return false;
        }
    }
    // Items: the first with a free slot, in the file's order; all or nothing.
    std::map<std::string, std::vector<std::size_t>> chosen;
    for (const auto& want : wanted) {
        const std::vector<PoolItem>& items = pools_[want.first];
        const std::vector<unsigned int>& used = used_[want.first];
        for (std::size_t i = 0; i < items.size() && chosen[want.first].size() < want.second; ++i) {
            if (used[i] < items[i].slots) {
                chosen[want.first].push_back(i);
            }
        }
        if (chosen[want.first].size() < want.second) {
            busyPool = want.first;
            return false;
        }
    }
    held = Held();
    for (const auto& lock : locks) {
        locks_[lock] = holder;
        held.locks.push_back(lock);
    }
    for (const auto& pool : chosen) {
        for (std::size_t i : pool.second) {
            ++used_[pool.first][i];
            held.items[pool.first].push_back(pools_[pool.first][i].id);
        }
    }
    return true;
}

void ResourceTable::release(const Held& held) {
    for (const auto& lock : held.locks) {
        locks_.erase(lock);
    }
    for (const auto& pool : held.items) {
        const std::vector<PoolItem>& items = pools_[pool.first];
        for (const auto& id : pool.second) {
            for (std::size_t i = 0; i < items.size(); ++i) {
                if (items[i].id == id && used_[pool.first][i] > 0) {
                    --used_[pool.first][i];
                    break;
                }
            }
        }
    }
}

std::string ResourceTable::holderOf(const std::string& lock) const {
    auto found = locks_.find(lock);
    return found == locks_.end() ? std::string() : found->second;
}

}  // namespace runner
}  // namespace robottestingframework
