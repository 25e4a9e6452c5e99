// The scheduler over a plan: suites at once on lanes, every event handed on in plan order from
// the caller's thread, depends across suites, locks, pools and exclusive suites.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "runner/model/test_executor.h"
#include "runner/plan/run_plan.h"
#include "runner/schedule/resources.h"
#include "runner/schedule/scheduler.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

// What runs at once, seen by the tests themselves.
struct Board {
    std::mutex mutex;
    int running = 0;
    int most = 0;
    std::map<std::string, int> byParam;  // tests running per param
    std::vector<std::string> overlaps;   // params seen running twice at once
};

// Each test waits `spec.timeout` seconds (used as a duration here) and fails when its param is
// "failed". Its lanes share the board.
class SleepingExecutor : public TestExecutor {
public:
    explicit SleepingExecutor(Board& board) : board_(board) {}
    TestStatus run(const TestSpec& spec, Test& self, TestResult& result) override {
        {
            std::lock_guard<std::mutex> lock(board_.mutex);
            board_.most = std::max(board_.most, ++board_.running);
            if (!spec.param.empty() && ++board_.byParam[spec.param] > 1) {
                board_.overlaps.push_back(spec.param);
            }
        }
        result.startTest(&self);
        std::this_thread::sleep_for(std::chrono::duration<double>(spec.timeout));
        if (spec.param == "failed") {
            result.addFailure(&self, TestMessage("no"));
        }
        result.endTest(&self);
        std::lock_guard<std::mutex> lock(board_.mutex);
        --board_.running;
        if (!spec.param.empty()) {
            --board_.byParam[spec.param];
        }
        return spec.param == "failed" ? TestStatus::Failed : TestStatus::Passed;
    }
    void interrupt() override {}
    std::unique_ptr<FixtureManager> makeFixture(const FixtureSpec&, std::string&) override {
        return nullptr;
    }
    std::unique_ptr<TestExecutor> makeLane() override {
        return std::make_unique<SleepingExecutor>(board_);
    }

private:
    Board& board_;
};

// The events the run's listeners get, with the thread they came on.
class Record : public TestListener {
public:
    void startTestSuite(const Test* suite) override { add("suite " + suite->getName()); }
    void endTestSuite(const Test* suite) override { add("end " + suite->getName()); }
    void endTest(const Test* test) override { add(test->getName()); }
    void addSkipped(const Test* test, TestMessage) override { add("skipped " + test->getName()); }
    std::vector<std::string> events;
    std::vector<std::thread::id> threads;

private:
    void add(const std::string& event) {
        events.push_back(event);
        threads.push_back(std::this_thread::get_id());
    }
};

SuiteSpec suite(const std::string& name, std::vector<std::string> tests, double seconds = 0.05,
                const std::string& param = "") {
    SuiteSpec spec;
    spec.name = name;
    for (const auto& test : tests) {
        TestSpec added;
        added.name = test;
        added.plugin = test + ".so";
        added.param = param;
        added.timeout = seconds;
        added.repetition = 1;
        spec.tests.push_back(added);
    }
    return spec;
}

ResourceSpec lock(const std::string& name) {
    ResourceSpec resource;
    resource.lock = name;
    return resource;
}

std::vector<std::string> runAll(RunPlan& plan, unsigned int jobs, ResourcePools pools = {}) {
    SchedulerSettings settings;
    settings.jobs = jobs;
    Scheduler scheduler(plan, std::move(pools), settings);
    TestResult result;
    Record record;
    result.addListener(&record);
    scheduler.run(result);
    for (const auto& id : record.threads) {
        EXPECT_EQ(id, std::this_thread::get_id());  // every event on the caller's thread
    }
    return record.events;
}

}  // namespace

TEST(Scheduler, SuitesRunAtOnceAndTheirEventsComeInPlanOrder) {
    Board board;
    SleepingExecutor executor(board);
    RunPlan plan(executor);
    // The first suite is the slowest: the others end first, and still come after it.
    plan.addSuite(suite("a", {"a1", "a2"}, 0.3));
    plan.addSuite(suite("b", {"b1", "b2"}));
    plan.addSuite(suite("c", {"c1"}));
    const std::vector<std::string> expected = {
        "suite a", "a1", "a2", "end a", "suite b", "b1", "b2", "end b", "suite c", "c1", "end c"};
    EXPECT_EQ(runAll(plan, 3), expected);
    EXPECT_EQ(board.most, 3);
    board.most = 0;
    EXPECT_EQ(runAll(plan, 1), expected);  // a second round, one at a time
    EXPECT_EQ(board.most, 1);
}

TEST(Scheduler, DependsAcrossSuitesSeesTheResultsOfOneAtATime) {
    Board board;
    SleepingExecutor executor(board);
    RunPlan plan(executor);
    plan.addSuite(suite("first", {"base"}, 0.2, "failed"));
    SuiteSpec second = suite("second", {"after"});
    second.tests[0].depends = {"base"};
    plan.addSuite(second);
    const std::vector<std::string> events = runAll(plan, 2);
    EXPECT_EQ(events, (std::vector<std::string>{"suite first", "base", "end first", "suite second",
                                                "skipped after", "after", "end second"}));
}

TEST(Scheduler, SuitesSharingALockNeverOverlapAndExclusiveRunsAlone) {
    Board board;
    SleepingExecutor executor(board);
    RunPlan plan(executor);
    for (const char* name : {"l1", "l2", "l3"}) {
        SuiteSpec spec = suite(name, {std::string(name) + "t"}, 0.05, "arm");
        spec.resources = {lock("robot:arm")};
        plan.addSuite(spec);
    }
    runAll(plan, 3);
    EXPECT_TRUE(board.overlaps.empty());

    Board alone;
    SleepingExecutor other(alone);
    RunPlan exclusive(other);
    exclusive.addSuite(suite("x1", {"x1t"}, 0.1));
    SuiteSpec only = suite("only", {"onlyt"}, 0.1);
    only.exclusive = true;
    exclusive.addSuite(only);
    exclusive.addSuite(suite("x2", {"x2t"}, 0.1));
    exclusive.addSuite(suite("x3", {"x3t"}, 0.1));
    runAll(exclusive, 4);
    EXPECT_EQ(alone.most, 2);  // x2 and x3 together, never with "only"
}

TEST(Scheduler, FailFastStartsNoSuiteAfterAFailure) {
    Board board;
    SleepingExecutor executor(board);
    RunPlan plan(executor);
    plan.gate().setFailFast(true);
    plan.addSuite(suite("bad", {"fails"}, 0.05, "failed"));
    plan.addSuite(suite("later", {"never"}));
    const std::vector<std::string> events = runAll(plan, 1);
    EXPECT_EQ(events.back(), "end later");
    EXPECT_NE(std::find(events.begin(), events.end(), "skipped never"), events.end());
}
