#include "runner/plan/world_logs.h"

#include "runner/plan/run_plan.h"

#include <map>
#include <set>
#include <string>

namespace robottestingframework {
namespace runner {

namespace {

// One word of a param, as a shell would quote it.
std::string quoted(const std::string& word) {
    std::string text = "'";
    for (char c : word) {
        text += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return text + "'";
}

// The world a process fixture starts, by the name that makes its log folder (<logdir> is
// rtf-logs/<name> by default): two world files of one name (world.xml in two suites' folders)
// would write one folder as one file would.
std::string worldOf(const FixtureSpec& fixture) {
    return worldNameOf(fixture.path.empty() ? fixture.plugin.str() : fixture.path.str());
}

}  // namespace

void separateWorldLogs(std::vector<SuiteSpec>& suites) {
    std::map<std::string, std::set<std::size_t>> startedBy;  // world name -> suites
    for (std::size_t s = 0; s < suites.size(); ++s) {
        for (const auto& fixture : suites[s].fixtures) {
            if (fixture.type == "process" && fixture.scope == FixtureSpec::Scope::Suite) {
                startedBy[worldOf(fixture)].insert(s);
            }
        }
    }
    for (const auto& world : startedBy) {
        if (world.second.size() < 2) {
            continue;
        }
        std::set<std::string> taken;
        for (std::size_t s : world.second) {
            SuiteSpec& suite = suites[s];
            std::string instance = suite.name;
            for (unsigned int n = 2; !taken.insert(instance).second; ++n) {
                instance = suite.name + "-" + std::to_string(n);
            }
            for (auto& fixture : suite.fixtures) {
                if (fixture.type == "process" && fixture.scope == FixtureSpec::Scope::Suite &&
                    worldOf(fixture) == world.first) {
                    fixture.param += (fixture.param.empty() ? "" : " ") +
                                     std::string("--instance ") + quoted(instance);
                }
            }
        }
    }
}

}  // namespace runner
}  // namespace robottestingframework
