// Runs the suites of a plan, up to N at once (-j N), as ninja runs commands: a plan of what is
// left, suites that are started and report when they are done, and one loop, on the caller's
// thread, that watches them all and decides what starts next. Each suite runs on a thread of
// its own with its own fixtures and workers (an executor lane); its tests stay in document
// order. Everything a suite reports comes back to the loop, which hands it on to the run's
// listeners: from that one thread, each suite whole and in plan order, so every output holds
// the same results as a run of one suite at a time.
//
// What used to depend on the order suites ran in is asked of the plan's results instead: a
// suite whose tests depend on tests of an earlier suite starts once that one ended; after a
// failure under --fail-fast no suite starts; an interruption reports every suite not started
// as interrupted. Locks, pool items and exclusive suites (resources.h) are taken here too.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <robottestingframework/TestResult.h>

#include "platform/file_descriptor.h"
#include "runner/plan/run_plan.h"
#include "runner/schedule/resources.h"
#include "runner/schedule/suite_events.h"

namespace robottestingframework {
namespace runner {

// What the console learns from the scheduler besides the ordered events.
class SchedulerView {
public:
    virtual ~SchedulerView() = default;
    // A suite's events, as soon as the loop takes them (not in plan order).
    virtual void events(const TestSuite& /*suite*/,
                        const std::vector<SuiteEvents::Event>& /*events*/) {}
    // A line to show now ("suite x waits for lock y").
    virtual void note(const std::string& line) = 0;
    // What runs now, one line, when it changed; empty when nothing runs.
    virtual void running(const std::string& /*line*/) {}
};

struct SchedulerSettings {
    unsigned int jobs = 1;
    // Run each suite on the scheduler's own thread, its events straight to the run's result,
    // one at a time: for tests in the runner's process (--isolation none), whose output is
    // caught from the process's own descriptors as it comes.
    bool inlineSuites = false;
    bool verbose = false;  // say which suite holds a lock another waits for
    // Set: suites with a private network run in this one instead of a new one each (a world
    // keeper's, --world DIR: the tests join the network their world lives in).
    std::shared_ptr<const platform::PrivateNetwork> network;
    SchedulerView* view = nullptr;
};

class Scheduler {
public:
    Scheduler(RunPlan& plan, ResourcePools pools, SchedulerSettings settings);
    ~Scheduler();
    Scheduler(const Scheduler&) = delete;
    Scheduler& operator=(const Scheduler&) = delete;

    // Runs every suite of the plan; `result` gets startTestRunner, each suite's events (in
    // plan order) and endTestRunner, all on this thread. May be called again (a new round).
    void run(TestResult& result);
    // Stops the run: the running suites are interrupted (their tear-downs run), the others
    // reported interrupted. Thread-safe; may be called again and again.
    void interrupt();

private:
    struct Job;
    void startReady();
    bool mayStart(Job& job);
    void start(Job& job);
    void notRun(Job& job, const TestMessage& reason, bool interrupted);
    void finish(Job& job);
    void collect(bool& changed);
    void wake();
    std::string runningLine() const;
    void releaseWorlds(Job& job);  // lets go the shared worlds a suite still holds
    void noteWorlds();             // the shared worlds' lines to the view
    void stopWorlds();             // at the end: every world still up, last started first

    RunPlan& plan_;
    ResourcePools pools_;
    ResourceTable table_;
    SchedulerSettings settings_;
    std::vector<std::unique_ptr<Job>> jobs_;
    std::vector<std::vector<std::size_t>> after_;  // per suite: earlier suites it depends on
    // What a suite file said before ${resource.NAME} was filled in, per suite: only the tests
    // that name a resource (a copy of every test's param would cost 10 000 strings for nothing).
    struct ResourceTemplate {
        std::size_t test;
        std::string param, environment;
    };
    std::vector<std::vector<ResourceTemplate>> testTemplates_;
    std::vector<std::vector<std::string>> fixtureParams_;
    // Per suite, its group of suites sharing worlds; per group, its private network.
    std::vector<std::size_t> groups_;
    std::vector<bool> groupPrivate_;
    std::vector<std::shared_ptr<const platform::PrivateNetwork>> groupNetworks_;
    TestResult* result_ = nullptr;  // during run()
    std::size_t running_ = 0;
    bool aloneRunning_ = false;  // an exclusive suite runs
    platform::FileDescriptor wakeRead_, wakeWrite_;
    std::atomic<bool> interrupted_{false};
};

}  // namespace runner
}  // namespace robottestingframework
