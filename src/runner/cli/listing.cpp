#include "runner/cli/listing.h"

#include <nlohmann/json.hpp>

#include <sstream>

#include "languages/test_loader.h"
#include "reporters/atomic_file.h"
#include "runner/model/stand_in_test.h"
#include "runner/model/test_id.h"
#include "runner/plan/run_plan.h"
#include "runner/plan/shared_world.h"
#include "variables/variables.h"

namespace robottestingframework {
namespace runner {

namespace {

// The type a test would be loaded as: its own, else the file's (empty: it would not load).
std::string typeOf(const TestSpec& test) {
    if (!test.type.empty() || test.path.empty()) {
        return test.type;
    }
    return languages::typeFromFile(test.path);
}

// A pool's item is given when the suite starts: until then it is shown as written.
std::string shown(const std::string& text) {
    return variables::fillResources(
        text, [](const std::string& pool) { return "${resource." + pool + "}"; });
}

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const auto& item : items) {
        text += (text.empty() ? "" : ",") + item;
    }
    return text;
}

// "suite/test": the test's id (model/test_id.h), which --filter selects it by.
std::string idOf(const SuiteSpec& suite, const TestSpec& test) {
    return testId(suite, test);
}

// "lock robot:arm, 2 of pool ros_domain, the machine alone (exclusive)".
std::string resourcesOf(const SuiteSpec& suite) {
    std::string text;
    for (const auto& resource : suite.resources) {
        text += text.empty() ? "" : ", ";
        text += resource.pool.empty()
                    ? "lock " + resource.lock
                    : std::to_string(resource.count) + " of pool " + resource.pool;
    }
    if (suite.exclusive) {
        text += std::string(text.empty() ? "" : ", ") + "the machine alone (exclusive)";
    }
    return text;
}

std::string seconds(double value) {
    std::ostringstream text;
    text << value << "s";
    return text.str();
}

}  // namespace

std::string listText(const std::vector<SuiteSpec>& suites, const std::vector<unsigned int>& shards,
                     unsigned int shardCount) {
    std::string text;
    std::size_t count = 0;
    for (std::size_t s = 0; s < suites.size(); ++s) {
        const SuiteSpec& suite = suites[s];
        text += "suite " + suite.name +
                (suite.where.file.empty() ? std::string() : " (" + suite.where.file + ")") +
                (s < shards.size() ? "  [shard " + std::to_string(shards[s]) + " of " +
                                         std::to_string(shardCount) + "]"
                                   : std::string()) +
                "\n";
        if (!suite.resources.empty() || suite.exclusive) {
            text += "  takes " + resourcesOf(suite) + "\n";
        }
        for (const auto& test : suite.tests) {
            ++count;
            text += "  " + idOf(suite, test) + "\n";
            const std::string type = typeOf(test);
            text += "      type " + (type.empty() ? std::string("(unknown)") : type) +
                    ", plug-in " +
                    (test.path.empty() ? test.plugin + " (not found)" : test.path.str()) + "\n";
            if (!test.param.empty()) {
                text += "      param " + shown(test.param) + "\n";
            }
            if (!test.tags.empty()) {
                text += "      tags " + joined(test.tags) + "\n";
            }
            if (test.timeout > 0) {
                text += "      timeout " + seconds(test.timeout) + "\n";
            }
            if (test.repetition > 1) {
                text += "      repetition " + std::to_string(test.repetition) + "\n";
            }
        }
    }
    text += std::to_string(count) + (count == 1 ? " test" : " tests") + " in " +
            std::to_string(suites.size()) + (suites.size() == 1 ? " suite" : " suites") + "\n";
    return text;
}

std::string listJson(const std::vector<SuiteSpec>& suites,
                     const std::vector<unsigned int>& shards) {
    nlohmann::json list = {{"suites", nlohmann::json::array()}};
    for (std::size_t s = 0; s < suites.size(); ++s) {
        const SuiteSpec& suite = suites[s];
        nlohmann::json fixtures = nlohmann::json::array();
        for (const auto& fixture : suite.fixtures) {
            fixtures.push_back(
                {{"plugin", fixture.plugin.str()},
                 {"path", fixture.path.str()},
                 {"type", fixture.type},
                 {"param", shown(fixture.param)},
                 {"scope", fixture.scope == FixtureSpec::Scope::Run ? "run" : "suite"}});
            if (fixture.scope == FixtureSpec::Scope::Run) {
                // What makes a shared world one (plan/shared_world.h): discover_tests gives the
                // suites that need it one CTest fixture and one keeper
                // (docs/how-to/ctest-worlds.md).
                const std::string file =
                    fixture.path.empty() ? fixture.plugin.str() : fixture.path.str();
                const std::string identity = sharedWorldIdentity(fixture);
                fixtures.back()["world"] = worldNameOf(file);
                fixtures.back()["world_file"] = identity.substr(0, identity.find('\n'));
                fixtures.back()["identity"] = identity;
            }
        }
        nlohmann::json tests = nlohmann::json::array();
        for (const auto& test : suite.tests) {
            tests.push_back({{"id", idOf(suite, test)},
                             {"name", PluginTest::displayName(test)},
                             {"type", typeOf(test)},
                             {"plugin", test.plugin.str()},
                             {"path", test.path.str()},
                             {"param", shown(test.param)},
                             {"environment", shown(test.environment)},
                             {"tags", test.tags},
                             {"timeout", test.timeout},
                             {"repetition", test.repetition},
                             {"depends", test.depends},
                             {"where", test.where.toString()}});
        }
        nlohmann::json resources = nlohmann::json::array();
        for (const auto& resource : suite.resources) {
            resources.push_back(resource.pool.empty() ? nlohmann::json{{"lock", resource.lock}}
                                                      : nlohmann::json{{"pool", resource.pool},
                                                                       {"count", resource.count}});
        }
        list["suites"].push_back(
            {{"name", suite.name},
             {"file", suite.where.file},
             {"resources", resources},
             {"exclusive", suite.exclusive},
             {"network", suite.network == SuiteSpec::Network::Private ? "private" : "host"},
             {"fixtures", fixtures},
             {"tests", tests}});
        if (s < shards.size()) {
            list["suites"].back()["shard"] = shards[s];
        }
    }
    // Invalid UTF-8 in a param is replaced, not a reason to write nothing.
    return list.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

bool writeListJson(const std::string& file, const std::vector<SuiteSpec>& suites,
                   std::string& error, const std::vector<unsigned int>& shards) {
    return reporters::writeFileAtomically(file, listJson(suites, shards), error);
}

std::string listVariablesText(const std::vector<SuiteSpec>& suites) {
    std::string text;
    for (const auto& suite : suites) {
        text += "suite " + suite.name +
                (suite.where.file.empty() ? std::string() : " (" + suite.where.file + ")") + "\n";
        if (suite.variables.empty()) {
            text += "  (no variables)\n";
        }
        for (const auto& variable : suite.variables) {
            text += "  " + variable.name + " = " + variable.value + "  (" + variable.origin + ")\n";
        }
    }
    return text;
}

}  // namespace runner
}  // namespace robottestingframework
