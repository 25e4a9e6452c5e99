// The model turned into something to run: one TestSuite per suite, one stand-in per test, the
// fixture managers the executor made. Owns them all; the TestRunner it fills only points.
#pragma once

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>

#include "runner/model/stand_in_test.h"
#include "runner/model/suite_model.h"
#include "runner/model/test_executor.h"
#include "runner/plan/run_gate.h"
#include "runner/plan/shared_world.h"
#include "runner/plan/suite_lane.h"

namespace robottestingframework {
namespace runner {

// What the command line says about every test (RTF 2.x's -p, -e, --repetition).
struct Overrides {
    std::string param;            // for tests without a param of their own
    std::string environment;      // appended to the suite's and the test's
    unsigned int repetition = 0;  // for tests without a repetition of their own; 0: once
    double timeout = 0;           // --timeout: for tests whose suite and own give none
    // --var NAME=VALUE: already applied when the suites were read (suite_file.h); kept to
    // warn about the ones nothing reads.
    std::vector<std::pair<std::string, std::string>> variables;
};

// The effective spec of each test of `suite` once the command line is applied. The timeout
// is the most specific given: the test's, the suite's <timeout>, then --timeout (0: none).
void applyOverrides(SuiteSpec& suite, const Overrides& overrides);

// The name a world file gives its world (<world name="...">), else its stem.
std::string worldNameOf(const std::string& file);

// A warning for each --var that no suite or test file of the run used and no world file of its
// process fixtures names as ${NAME}: nothing would read it, and a value silently ignored is a test
// run against the wrong thing.
std::vector<std::string> unreadVariables(const std::vector<SuiteSpec>& suites,
                                         const Overrides& overrides);

class RunPlan {
public:
    explicit RunPlan(TestExecutor& executor);
    ~RunPlan();
    RunPlan(const RunPlan&) = delete;
    RunPlan& operator=(const RunPlan&) = delete;

    // Adds a suite to run after the ones already added. Its fixtures are made now; one that
    // cannot be made fails the suite's set-up with the reason when the suite runs.
    // `sharedWorlds`, when given, stands in for all its shared worlds (scope="run"), in the
    // place of the first of them: a keeper's world under CTest (--shared-worlds DIR).
    void addSuite(SuiteSpec spec, FixtureManager* sharedWorlds = nullptr);
    // --retries: each test added from now on that fails runs again up to `retries` times.
    void setRetries(unsigned int retries) { retries_ = retries; }

    TestRunner& runner() { return runner_; }
    // Decides which tests are skipped before they run (depends, --fail-fast); it must also
    // listen to the run's result.
    RunGate& gate() { return gate_; }
    // Cuts short a fixture set-up or check in progress (the run was interrupted); tear-downs
    // still run. Thread-safe.
    void interruptFixtures();
    std::size_t testCount() const { return tests_.size(); }

    // The suites in plan order, for the scheduler (scheduler.h).
    std::size_t suiteCount() const { return suites_.size(); }
    TestSuite& suite(std::size_t index) { return suites_[index]; }
    // Its spec; the tests' param and environment may still be changed before it runs.
    SuiteSpec& spec(std::size_t index) { return specs_[index]; }
    // The executor its tests run through.
    SuiteLane& lane(std::size_t index) { return lanes_[index]; }
    // Its fixture managers, in document order (one per FixtureSpec).
    std::vector<FixtureManager*> fixtures(std::size_t index) const;
    // The stand-ins of its tests, in order.
    std::vector<PluginTest*> tests(std::size_t index);

    // The shared worlds (scope="run" fixtures), one per identity, in the order suites first
    // named them; a suite's place for one is a SharedWorldFixture among its fixtures.
    std::size_t worldCount() const { return worlds_.size(); }
    SharedWorld& world(std::size_t index) { return worlds_[index]; }
    // Its places for shared worlds, in document order.
    std::vector<SharedWorldFixture*> sharedWorlds(std::size_t index) const;
    // Per suite, its group of suites linked through shared worlds (sharedWorldGroups).
    std::vector<std::size_t> worldGroups() const;

private:
    TestExecutor& executor_;
    TestRunner runner_;
    std::deque<SuiteSpec> specs_;  // a deque: the stand-ins point into it
    std::deque<TestSuite> suites_;
    std::deque<SuiteLane> lanes_;
    std::vector<std::size_t> firstFixture_, firstTest_;  // per suite, into fixtures_ and tests_
    std::deque<PluginTest> tests_;
    std::vector<std::unique_ptr<FixtureManager>> fixtures_;
    std::deque<SharedWorld> worlds_;
    std::map<std::string, std::size_t> worldByIdentity_;
    std::vector<std::vector<std::size_t>> worldUsers_;  // per world, the suites naming it
    RunGate gate_{tests_};
    unsigned int retries_ = 0;
};

}  // namespace runner
}  // namespace robottestingframework
