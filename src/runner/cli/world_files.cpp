#include "runner/cli/world_files.h"

#include <filesystem>
#include <map>

#include <pugixml.hpp>

#include "fixtures/process/process_fixture.h"
#include "runner/plan/shared_world.h"
#include "variables/variables.h"

namespace robottestingframework {
namespace runner {

namespace {

// The first `count` items of each pool the suite takes, as the scheduler would write them.
std::map<std::string, std::string> sampleItems(const SuiteSpec& suite, const ResourcePools& pools) {
    std::map<std::string, std::string> items;
    for (const ResourceSpec& resource : suite.resources) {
        auto found = pools.pools.find(resource.pool);
        if (resource.pool.empty() || found == pools.pools.end()) {
            continue;
        }
        std::string text;
        for (std::size_t i = 0; i < found->second.size() && i < resource.count; ++i) {
            text += (text.empty() ? "" : ",") + found->second[i].id;
        }
        items[resource.pool] = text;
    }
    return items;
}

// The name a world file gives its world: <world name="..."> or the file's stem.
std::string worldName(const std::string& file) {
    pugi::xml_document document;
    if (document.load_file(file.c_str())) {
        const std::string name = document.document_element().attribute("name").value();
        if (!name.empty()) {
            return name;
        }
    }
    return std::filesystem::path(file).stem().string();
}

// Two shared worlds of one name that are not the same world (another file, another param).
std::string checkSharedWorlds(const std::vector<SuiteSpec>& suites) {
    struct First {
        std::string identity;
        const FixtureSpec* fixture;
    };
    std::map<std::string, First> byName;
    for (const SuiteSpec& suite : suites) {
        for (const FixtureSpec& fixture : suite.fixtures) {
            if (fixture.scope != FixtureSpec::Scope::Run || fixture.path.empty()) {
                continue;
            }
            const std::string identity = sharedWorldIdentity(fixture);
            const std::string name = worldName(fixture.path);
            auto found = byName.emplace(name, First{identity, &fixture}).first;
            if (found->second.identity == identity) {
                continue;
            }
            const FixtureSpec& first = *found->second.fixture;
            const std::string what =
                first.path.str() != fixture.path.str()
                    ? "world file " + first.path.str() + " there, " + fixture.path.str() + " here"
                    : "param '" + first.param + "' there, '" + fixture.param + "' here";
            return fixture.where.toString() +
                   ": a shared world declared twice with different "
                   "contents: world '" +
                   name + "' (scope=\"run\") is also declared at " + first.where.toString() + " (" +
                   what +
                   "); suites share a world when they name the same world file with the same "
                   "param and variables, or give their worlds different names";
        }
    }
    return {};
}

}  // namespace

std::string checkWorldFiles(const std::vector<SuiteSpec>& suites, const ResourcePools& pools) {
    std::map<std::pair<std::string, std::string>, bool> checked;  // (file, param) read already
    for (const SuiteSpec& suite : suites) {
        for (const FixtureSpec& fixture : suite.fixtures) {
            if (fixture.type != "process") {
                continue;
            }
            const std::string where = fixture.where.toString();
            if (fixture.path.empty()) {
                // Not searched for as a plug-in: a world file is beside its suite (or a path).
                std::error_code ignored;
                const auto folder = std::filesystem::path(fixture.where.file.str()).parent_path();
                const std::string looked =
                    std::filesystem::absolute(folder / fixture.plugin.str(), ignored)
                        .lexically_normal()
                        .string();
                return where + ": the world file '" + fixture.plugin.str() +
                       "' of the process fixture does not exist (looked for " + looked + ")";
            }
            const std::map<std::string, std::string> items = sampleItems(suite, pools);
            const std::string param =
                variables::fillResources(fixture.param, [&items](const std::string& pool) {
                    auto found = items.find(pool);
                    return found != items.end() ? found->second : std::string();
                });
            if (!checked.emplace(std::make_pair(fixture.path.str(), param), true).second) {
                continue;
            }
            const std::string problem = fixtures::checkWorldFile(fixture.path, param);
            if (!problem.empty()) {
                return problem + " (the world file of the process fixture at " + where + ")";
            }
        }
    }
    return checkSharedWorlds(suites);
}

}  // namespace runner
}  // namespace robottestingframework
