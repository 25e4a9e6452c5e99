#include "runner/cli/world_files.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <pugixml.hpp>

#include "fixtures/process/process_fixture.h"
#include "fixtures/process/world_file.h"
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

// One word for a param, as a shell would quote it.
std::string shellWord(const std::string& word) {
    std::string text = "'";
    for (char c : word) {
        text += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return text + "'";
}

// Whether `text` reads ${NAME} (${NAME} or ${NAME followed by what is not part of a name).
bool reads(const std::string& text, const std::string& name) {
    const std::string mark = "${" + name;
    for (std::size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at + 1)) {
        const std::size_t after = at + mark.size();
        if (after >= text.size()) {
            return true;
        }
        const char c = text[after];
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) {
            return true;
        }
    }
    return false;
}

// A param as words, for a message: "--var speed=2 --logdir logs".
std::string shown(const std::string& param) {
    std::vector<std::string> words;
    std::string error;
    if (!fixtures::splitCommandLine(param, words, error)) {
        return param;
    }
    std::string text;
    for (const auto& word : words) {
        text += (text.empty() ? "" : " ") + word;
    }
    return text;
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
                    : "param \"" + shown(first.param) + "\" there, \"" + shown(fixture.param) +
                          "\" here";
            return fixture.where.toString() +
                   ": a shared world declared twice with different "
                   "contents: world '" +
                   name + "' (scope=\"run\") is also declared at " + first.where.toString() + " (" +
                   what +
                   "); suites share a world when they name the same world file with the same "
                   "param and the same values of the variables it reads, or give their worlds "
                   "different names";
        }
    }
    return {};
}

}  // namespace

void keepSharedWorldVariables(std::vector<SuiteSpec>& suites) {
    std::map<std::string, std::string> texts;  // world file -> its text
    for (SuiteSpec& suite : suites) {
        for (FixtureSpec& fixture : suite.fixtures) {
            if (fixture.scope != FixtureSpec::Scope::Run || fixture.path.empty()) {
                continue;
            }
            auto found = texts.find(fixture.path.str());
            if (found == texts.end()) {
                std::ifstream in(fixture.path.str(), std::ios::binary);
                std::ostringstream text;
                text << in.rdbuf();
                found = texts.emplace(fixture.path.str(), text.str()).first;
            }
            std::vector<std::string> words;
            std::string error;
            if (!fixtures::splitCommandLine(fixture.param, words, error)) {
                continue;  // checkWorldFiles says what is wrong with it
            }
            std::string kept;
            for (std::size_t i = 0; i < words.size(); ++i) {
                if (words[i] == "--var" && i + 1 < words.size()) {
                    const std::string name = words[i + 1].substr(0, words[i + 1].find('='));
                    if (!reads(found->second, name)) {
                        ++i;
                        continue;
                    }
                }
                kept += (kept.empty() ? "" : " ") + shellWord(words[i]);
            }
            fixture.param = kept;
        }
    }
}

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
