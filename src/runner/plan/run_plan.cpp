#include "runner/plan/run_plan.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>

namespace robottestingframework {
namespace runner {

namespace {

void append(std::string& text, const std::string& more) {
    if (!more.empty()) {
        text += (text.empty() ? "" : " ") + more;
    }
}

// Stands for a fixture that could not be loaded: its set-up fails with the loader's reason,
// so the suite reports it and skips its tests like for any fixture that fails.
class UnloadedFixture : public FixtureManager {
public:
    explicit UnloadedFixture(std::string reason) : reason_(std::move(reason)) {}
    bool setup(int, char**) override { throw std::runtime_error(reason_); }

private:
    std::string reason_;
};

bool isProcessFixture(const FixtureSpec& fixture) {
    return fixture.type == "process" && !fixture.path.empty();
}

// A world file's text, for a look at the variables it names; a world file is small.
std::string worldText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string text;
    char chunk[65536];
    const std::size_t limit = 16 * 1024 * 1024;
    while (in && text.size() < limit) {
        in.read(chunk, sizeof chunk);
        text.append(chunk, static_cast<std::size_t>(in.gcount()));
    }
    return text;
}

}  // namespace

std::string worldNameOf(const std::string& file) {
    static const std::regex named(R"(<world\b[^>]*?\bname\s*=\s*["']([^"']*)["'])");
    const std::string text = worldText(file).substr(0, 65536);
    std::smatch match;
    if (std::regex_search(text, match, named) && match[1].length() > 0) {
        return match[1];
    }
    return std::filesystem::path(file).stem().string();
}

std::vector<std::string> unreadVariables(const std::vector<SuiteSpec>& suites,
                                         const Overrides& overrides) {
    std::vector<std::string> worlds;
    for (const auto& suite : suites) {
        for (const auto& fixture : suite.fixtures) {
            if (isProcessFixture(fixture)) {
                worlds.push_back(worldText(fixture.path));
            }
        }
    }
    std::vector<std::string> warnings;
    for (const auto& variable : overrides.variables) {
        const std::string use = "${" + variable.first + "}";
        bool read = false;
        for (const auto& suite : suites) {
            const auto& used = suite.variablesUsed;
            read = read || std::find(used.begin(), used.end(), variable.first) != used.end();
        }
        for (const auto& world : worlds) {
            read = read || world.find(use) != std::string::npos;
        }
        if (!read) {
            warnings.push_back("warning: --var " + variable.first + "=" + variable.second +
                               " is not used: no suite, test file or world file of a process "
                               "fixture in this run reads " +
                               use);
        }
    }
    return warnings;
}

void applyOverrides(SuiteSpec& suite, const Overrides& overrides) {
    // What comes from the suite and the command line alone is one string for all its tests.
    const SharedString param = overrides.param;
    std::string suiteWide = suite.environment;
    append(suiteWide, overrides.environment);
    const SharedString environment = suiteWide;
    for (auto& test : suite.tests) {
        if (test.param.empty()) {
            test.param = param;
        }
        // Suite first, then the test's own, then the command line.
        if (test.environment.empty()) {
            test.environment = environment;
        } else {
            std::string own = suite.environment;
            append(own, test.environment);
            append(own, overrides.environment);
            test.environment = own;
        }
        if (test.repetition == 0) {
            test.repetition = overrides.repetition == 0 ? 1 : overrides.repetition;
        }
        if (test.timeout <= 0) {
            test.timeout = suite.timeout > 0 ? suite.timeout : overrides.timeout;
        }
    }
}

RunPlan::RunPlan(TestExecutor& executor) : executor_(executor) {
    runner_.setGate(&gate_);
}

RunPlan::~RunPlan() = default;

void RunPlan::interruptFixtures() {
    for (const auto& fixture : fixtures_) {
        if (auto* interruptible = dynamic_cast<InterruptibleFixture*>(fixture.get())) {
            interruptible->interruptCall();
        }
    }
}

std::vector<FixtureManager*> RunPlan::fixtures(std::size_t index) const {
    std::vector<FixtureManager*> managers;
    const std::size_t end =
        index + 1 < firstFixture_.size() ? firstFixture_[index + 1] : fixtures_.size();
    for (std::size_t i = firstFixture_[index]; i < end; ++i) {
        managers.push_back(fixtures_[i].get());
    }
    return managers;
}

std::vector<PluginTest*> RunPlan::tests(std::size_t index) {
    std::vector<PluginTest*> standIns;
    const std::size_t end = index + 1 < firstTest_.size() ? firstTest_[index + 1] : tests_.size();
    for (std::size_t i = firstTest_[index]; i < end; ++i) {
        standIns.push_back(&tests_[i]);
    }
    return standIns;
}

std::vector<SharedWorldFixture*> RunPlan::sharedWorlds(std::size_t index) const {
    std::vector<SharedWorldFixture*> places;
    for (FixtureManager* fixture : fixtures(index)) {
        if (auto* place = dynamic_cast<SharedWorldFixture*>(fixture)) {
            places.push_back(place);
        }
    }
    return places;
}

std::vector<std::size_t> RunPlan::worldGroups() const {
    return sharedWorldGroups(specs_.size(), worldUsers_);
}

void RunPlan::addSuite(SuiteSpec spec, FixtureManager* sharedWorlds) {
    const SuiteSpec& owned = specs_.emplace_back(std::move(spec));
    SuiteLane& lane = lanes_.emplace_back(executor_);
    firstFixture_.push_back(fixtures_.size());
    firstTest_.push_back(tests_.size());
    TestSuite& suite = suites_.emplace_back(owned.name);
    suite.setDescription(owned.description);
    suite.getId();  // ids are given here, in plan order, before any event carries them
    const std::size_t suiteIndex = specs_.size() - 1;
    bool sharedWorldsAdded = false;
    for (const auto& fixture : owned.fixtures) {
        if (fixture.scope == FixtureSpec::Scope::Run && sharedWorlds) {
            if (!sharedWorldsAdded) {
                suite.addFixtureManager(sharedWorlds);
                sharedWorldsAdded = true;
            }
            continue;
        }
        if (fixture.scope == FixtureSpec::Scope::Run) {
            const std::string identity = sharedWorldIdentity(fixture);
            auto found = worldByIdentity_.find(identity);
            if (found == worldByIdentity_.end()) {
                const std::string file =
                    fixture.path.empty() ? fixture.plugin.str() : fixture.path.str();
                TestExecutor* executor = &executor_;
                const FixtureSpec made = fixture;
                worlds_.emplace_back(worldNameOf(file), [executor, made](std::string& error) {
                    return executor->makeFixture(made, error);
                });
                worldUsers_.emplace_back();
                found = worldByIdentity_.emplace(identity, worlds_.size() - 1).first;
            }
            SharedWorld& world = worlds_[found->second];
            world.addUser();
            worldUsers_[found->second].push_back(suiteIndex);
            auto standIn = std::make_unique<SharedWorldFixture>(world);
            suite.addFixtureManager(standIn.get());
            fixtures_.push_back(std::move(standIn));
            continue;
        }
        std::string error;
        std::unique_ptr<FixtureManager> manager = executor_.makeFixture(fixture, error);
        if (!manager) {
            manager =
                std::make_unique<UnloadedFixture>("cannot load " + fixture.plugin + ": " + error);
            manager->setName(fixture.plugin);
        }
        suite.addFixtureManager(manager.get());
        fixtures_.push_back(std::move(manager));
    }
    for (const auto& test : owned.tests) {
        PluginTest& planned = tests_.emplace_back(test, lane);
        planned.getId();
        planned.setRetries(retries_);
        suite.addTest(&planned);
    }
    runner_.addTest(&suite);
}

}  // namespace runner
}  // namespace robottestingframework
