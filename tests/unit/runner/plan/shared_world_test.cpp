// Shared worlds (scope="run") through the plan and the scheduler, with fixtures that only note
// what is done to them: one start for every suite that names a world, its stop after the last
// of them (and not while one is pending), several stopped in the reverse order of their starts,
// a world that fails or collapses fails exactly its suites, and the groups of suites linked
// through worlds (one private network each).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <robottestingframework/Exception.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestSuite.h>

#include "runner/model/test_executor.h"
#include "runner/plan/run_plan.h"
#include "runner/plan/shared_world.h"
#include "runner/schedule/scheduler.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

struct Journal {
    std::mutex mutex;
    std::vector<std::string> lines;
    std::vector<FixtureManager*> worlds;  // made so far
    void add(const std::string& line) {
        std::lock_guard<std::mutex> lock(mutex);
        lines.push_back(line);
    }
    std::size_t count(const std::string& line) {
        std::lock_guard<std::mutex> lock(mutex);
        return std::count(lines.begin(), lines.end(), line);
    }
};

// A world: its param says how long it takes to start and whether it fails.
class NotedWorld : public FixtureManager {
public:
    NotedWorld(Journal& journal, std::string name) : journal_(journal), name_(std::move(name)) {}
    bool setup(int, char**) override {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        journal_.add("start " + name_);
        if (getParam() == "fails") {
            throw TestErrorException(TestMessage("world " + name_ + " cannot start"));
        }
        return true;
    }
    void tearDown() override { journal_.add("stop " + name_); }

private:
    Journal& journal_;
    std::string name_;
};

// Tests note their name; a test whose param is "collapse" makes the first world collapse.
class WorldExecutor : public TestExecutor {
public:
    explicit WorldExecutor(Journal& journal) : journal_(journal) {}
    TestStatus run(const TestSpec& spec, Test& self, TestResult& result) override {
        result.startTest(&self);
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
        journal_.add(spec.name.str());
        if (spec.param.str() == "collapse") {
            FixtureManager* world = nullptr;
            {
                std::lock_guard<std::mutex> lock(journal_.mutex);
                world = journal_.worlds.front();
            }
            world->getDispatcher()->fixtureCollapsed(TestMessage("the simulator died"));
        }
        result.endTest(&self);
        return TestStatus::Passed;
    }
    void interrupt() override {}
    std::unique_ptr<FixtureManager> makeFixture(const FixtureSpec& spec, std::string&) override {
        auto world = std::make_unique<NotedWorld>(
            journal_, spec.path.str().substr(spec.path.str().rfind('/') + 1));
        world->setParam(spec.param);
        std::lock_guard<std::mutex> lock(journal_.mutex);
        journal_.worlds.push_back(world.get());
        return world;
    }
    std::unique_ptr<TestExecutor> makeLane() override {
        return std::make_unique<WorldExecutor>(journal_);
    }

private:
    Journal& journal_;
};

FixtureSpec sharedWorld(const std::string& name, const std::string& param = "") {
    FixtureSpec fixture;
    fixture.plugin = name;
    fixture.path = "/nowhere/" + name;
    fixture.type = "process";
    fixture.param = param;
    fixture.scope = FixtureSpec::Scope::Run;
    return fixture;
}

SuiteSpec suite(const std::string& name, std::vector<FixtureSpec> worlds, int tests = 2,
                const std::string& param = "") {
    SuiteSpec spec;
    spec.name = name;
    spec.fixtures = std::move(worlds);
    for (int t = 0; t < tests; ++t) {
        TestSpec test;
        test.name = name + std::to_string(t + 1);
        test.plugin = "t.so";
        test.param = param;
        test.repetition = 1;
        spec.tests.push_back(test);
    }
    return spec;
}

class Skips : public TestListener {
public:
    void addSkipped(const Test* test, TestMessage message) override {
        skipped.push_back(test->getName() + ": " + message.getMessage());
    }
    void addError(const Test* test, TestMessage message) override {
        errors.push_back(test->getName() + ": " + message.getMessage());
    }
    std::vector<std::string> skipped, errors;
};

Skips runAll(RunPlan& plan, unsigned int jobs) {
    SchedulerSettings settings;
    settings.jobs = jobs;
    Scheduler scheduler(plan, ResourcePools(), settings);
    TestResult result;
    Skips skips;
    result.addListener(&skips);
    scheduler.run(result);
    return skips;
}

}  // namespace

class SharedWorlds : public ::testing::TestWithParam<unsigned int> {};

TEST_P(SharedWorlds, ThreeSuitesStartTheWorldOnceAndTheLastStopsIt) {
    Journal journal;
    WorldExecutor executor(journal);
    RunPlan plan(executor);
    for (const char* name : {"a", "b", "c"}) {
        plan.addSuite(suite(name, {sharedWorld("lab.xml")}));
    }
    ASSERT_EQ(plan.worldCount(), 1u);
    EXPECT_EQ(plan.world(0).name(), "lab");
    const Skips skips = runAll(plan, GetParam());
    EXPECT_TRUE(skips.skipped.empty());
    ASSERT_EQ(journal.lines.size(), 8u);
    EXPECT_EQ(journal.lines.front(), "start lab.xml");
    EXPECT_EQ(journal.lines.back(), "stop lab.xml");
    EXPECT_EQ(journal.count("start lab.xml"), 1u);
    EXPECT_EQ(journal.worlds.size(), 1u);
}

TEST_P(SharedWorlds, TwoWorldsStopInTheReverseOrderOfTheirStarts) {
    Journal journal;
    WorldExecutor executor(journal);
    RunPlan plan(executor);
    for (const char* name : {"a", "b", "c"}) {
        plan.addSuite(suite(name, {sharedWorld("sim.xml"), sharedWorld("broker.xml")}));
    }
    runAll(plan, GetParam());
    ASSERT_EQ(journal.lines.size(), 10u);
    EXPECT_EQ(journal.lines[0], "start sim.xml");
    EXPECT_EQ(journal.lines[1], "start broker.xml");
    EXPECT_EQ(journal.lines[8], "stop broker.xml");
    EXPECT_EQ(journal.lines[9], "stop sim.xml");
}

TEST_P(SharedWorlds, AWorldThatFailsToStartFailsExactlyItsSuites) {
    Journal journal;
    WorldExecutor executor(journal);
    RunPlan plan(executor);
    plan.addSuite(suite("a", {sharedWorld("lab.xml", "fails")}));
    plan.addSuite(suite("other", {}));
    plan.addSuite(suite("b", {sharedWorld("lab.xml", "fails")}));
    const Skips skips = runAll(plan, GetParam());
    EXPECT_EQ(journal.count("start lab.xml"), 1u);  // tried once
    EXPECT_EQ(journal.count("stop lab.xml"), 0u);
    EXPECT_EQ(journal.count("other1"), 1u);
    ASSERT_EQ(skips.skipped.size(), 4u);
    for (const auto& line : skips.skipped) {
        // One line referring to the suite's error, which says the reason once.
        EXPECT_NE(line.find("the suite's fixture failed (see the suite's error)"),
                  std::string::npos)
            << line;
        EXPECT_EQ(line.find("other"), std::string::npos);
    }
    std::vector<std::string> failed;
    for (const auto& line : skips.errors) {
        if (line.find("shared world 'lab' did not start: world lab.xml cannot start") !=
            std::string::npos) {
            failed.push_back(line.substr(0, line.find(':')));
        }
    }
    std::sort(failed.begin(), failed.end());
    EXPECT_EQ(failed, (std::vector<std::string>{"a", "b"}));
}

INSTANTIATE_TEST_SUITE_P(Jobs, SharedWorlds, ::testing::Values(1u, 3u));

TEST(SharedWorld, APendingSuiteKeepsItUp) {
    Journal journal;
    WorldExecutor executor(journal);
    RunPlan plan(executor);
    plan.addSuite(suite("a", {sharedWorld("lab.xml")}, 1));
    plan.addSuite(suite("middle", {}, 1));
    plan.addSuite(suite("b", {sharedWorld("lab.xml")}, 1));
    runAll(plan, 1);
    EXPECT_EQ(journal.lines,
              (std::vector<std::string>{"start lab.xml", "a1", "middle1", "b1", "stop lab.xml"}));
}

TEST(SharedWorld, ACollapseInterruptsItsSuiteAndFailsThePendingOnes) {
    Journal journal;
    WorldExecutor executor(journal);
    RunPlan plan(executor);
    plan.addSuite(suite("a", {sharedWorld("lab.xml")}, 2, "collapse"));
    plan.addSuite(suite("other", {}, 1));
    plan.addSuite(suite("b", {sharedWorld("lab.xml")}, 1));
    const Skips skips = runAll(plan, 1);
    EXPECT_EQ(journal.count("a1"), 1u);
    EXPECT_EQ(journal.count("a2"), 0u);  // the rest of the suite stopped
    EXPECT_EQ(journal.count("other1"), 1u);
    EXPECT_EQ(journal.count("b1"), 0u);
    EXPECT_EQ(journal.count("stop lab.xml"), 1u);  // a collapsed world is still stopped
    bool pendingSkipped = false;
    for (const auto& line : skips.skipped) {
        pendingSkipped =
            pendingSkipped ||
            line.rfind("b1: the suite's fixture failed (see the suite's error): ", 0) == 0;
    }
    EXPECT_TRUE(pendingSkipped);
    bool pendingFailed = false;  // the suite's error says why, once
    for (const auto& line : skips.errors) {
        pendingFailed =
            pendingFailed || (line.rfind("b: ", 0) == 0 &&
                              line.find("collapsed before this suite") != std::string::npos &&
                              line.find("the simulator died") != std::string::npos);
    }
    EXPECT_TRUE(pendingFailed);
}

TEST(SharedWorld, SuitesNotRunLetItGo) {
    Journal journal;
    WorldExecutor executor(journal);
    RunPlan plan(executor);
    plan.gate().setFailFast(true);
    SuiteSpec failing = suite("a", {sharedWorld("lab.xml")}, 1);
    failing.fixtures.push_back(sharedWorld("broken.xml", "fails"));
    plan.addSuite(failing);
    plan.addSuite(suite("b", {sharedWorld("lab.xml")}, 1));
    runAll(plan, 1);
    EXPECT_EQ(journal.count("start lab.xml"), 1u);
    EXPECT_EQ(journal.count("stop lab.xml"), 1u);
    EXPECT_EQ(journal.lines.back(), "stop lab.xml");
}

TEST(SharedWorld, DifferentParamsAreDifferentWorlds) {
    Journal journal;
    WorldExecutor executor(journal);
    RunPlan plan(executor);
    plan.addSuite(suite("a", {sharedWorld("lab.xml", "--var x=1")}, 1));
    plan.addSuite(suite("b", {sharedWorld("lab.xml", "--var x=2")}, 1));
    plan.addSuite(suite("c", {sharedWorld("lab.xml", "--var x=1")}, 1));
    EXPECT_EQ(plan.worldCount(), 2u);
    EXPECT_EQ(plan.world(0).users(), 2u);
    EXPECT_EQ(plan.worldGroups(), (std::vector<std::size_t>{0, 1, 0}));
}

TEST(SharedWorld, GroupsLinkSuitesThroughTheWorldsTheyShare) {
    // Worlds: {0,2}, {2,4}, {1}: suites 0, 2, 4 form one group; 1 and 3 their own.
    EXPECT_EQ(sharedWorldGroups(5, {{0, 2}, {2, 4}, {1}}),
              (std::vector<std::size_t>{0, 1, 0, 3, 0}));
    EXPECT_EQ(sharedWorldGroups(3, {{2, 1}}), (std::vector<std::size_t>{0, 1, 1}));
    EXPECT_EQ(sharedWorldGroups(0, {}), (std::vector<std::size_t>{}));
}

TEST(SharedWorld, ItsPhasesReachTheReportsAsWorldEvents) {
    Journal journal;
    WorldExecutor executor(journal);
    RunPlan plan(executor);
    plan.addSuite(suite("a", {sharedWorld("lab.xml")}, 1));
    plan.addSuite(suite("b", {sharedWorld("lab.xml")}, 1));
    plan.addSuite(suite("c", {sharedWorld("broken.xml", "fails")}, 1));
    SchedulerSettings settings;
    settings.jobs = 2;
    Scheduler scheduler(plan, ResourcePools(), settings);
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    scheduler.run(result);
    ASSERT_EQ(collector.worlds().size(), 2u);
    const WorldRecord* lab = nullptr;
    const WorldRecord* broken = nullptr;
    for (const WorldRecord& world : collector.worlds()) {
        (world.name == "lab" ? lab : broken) = &world;
    }
    ASSERT_NE(lab, nullptr);
    ASSERT_NE(broken, nullptr);
    EXPECT_EQ(lab->users, "2 suites");
    EXPECT_GE(lab->start, 0);
    EXPECT_GE(lab->ready - lab->start, 0.09);  // the fake world takes 100 ms to start
    EXPECT_GT(lab->stop, lab->ready);
    EXPECT_LT(lab->failed, 0);
    EXPECT_EQ(broken->users, "1 suite");
    EXPECT_LT(broken->ready, 0);
    EXPECT_GE(broken->failed, broken->start);
    EXPECT_NE(broken->reason.find("world broken.xml cannot start"), std::string::npos);
    // About no test: no suite's record holds them, and the counts are the suites'.
    EXPECT_EQ(collector.suiteCount(), 3u);
    EXPECT_EQ(collector.testCount(), 2u);  // c's is not counted: its fixture failed (RTF 2.x)
}

namespace {

// A world whose set-up blocks until interrupted (or 5 s), made slowly (200 ms).
class BlockingWorld : public FixtureManager, public InterruptibleFixture {
public:
    bool setup(int, char**) override {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait_for(lock, std::chrono::seconds(5), [this] { return interrupted_; });
        if (interrupted_) {
            throw TestErrorException(TestMessage("setup interrupted"));
        }
        return true;
    }
    void tearDown() override {}
    void interruptCall() override {
        std::lock_guard<std::mutex> lock(mutex_);
        interrupted_ = true;
        changed_.notify_all();
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    bool interrupted_ = false;
};

class NoEvents : public FixtureEvents {
public:
    void fixtureCollapsed(TestMessage) override {}
};

}  // namespace

// Ctrl-C while the world's manager is still being made (a worker started, a plug-in loaded):
// the start does not go on to await the world; the suites fail as interrupted at once.
TEST(SharedWorld, AnInterruptWhileItsManagerIsMadeStopsItsStart) {
    SharedWorld world("lab", [](std::string&) -> std::unique_ptr<FixtureManager> {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        return std::make_unique<BlockingWorld>();
    });
    world.addUser();
    world.reset();
    NoEvents suite;
    TestResult result;
    TestMessage failure;
    const auto began = std::chrono::steady_clock::now();
    std::thread interrupter([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        world.interrupt();
    });
    EXPECT_FALSE(world.acquire(&suite, result, nullptr, failure));
    interrupter.join();
    EXPECT_LT(std::chrono::steady_clock::now() - began, std::chrono::seconds(2));
    EXPECT_EQ(failure.getMessage(), "interrupted while shared world 'lab' was starting");
    EXPECT_EQ(world.state(), SharedWorld::State::Failed);
    world.release(&suite, nullptr, nullptr);
}
