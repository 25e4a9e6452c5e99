// Runs each test in a worker process forked by the fork server, so that nothing a test does
// (crash, abort, exit, hang, stray children) can take the runner down. Fixtures run in a
// worker of their own that lives for the whole suite.
//
// The runner makes one IsolatedExecutor per run, on the thread that runs the tests (the fork
// server takes its parent-death signal from that thread), and destroys it at the end, which
// ends every process the run started. If the runner dies instead, the fork server does that.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "isolation/fork_server_client.h"
#include "platform/file_descriptor.h"
#include "runner/model/test_executor.h"

namespace robottestingframework {
namespace isolation {

struct IsolationOptions {
    std::string workerPath;              // empty: findWorker()
    double killGrace = 1.0;              // seconds between SIGTERM and SIGKILL when stopping a test
    double fixtureTimeout = 120.0;       // bound on each fixture setup/check/tearDown; 0: none
    std::size_t outputTail = 64 * 1024;  // bytes of a test's output kept for the report
    bool verbose = false;                // the fork server says which interpreters it pre-started
    // Fork servers started with the executor: one for each lane that may run at once (--jobs),
    // so that parallel suites do not queue for one another's forks.
    std::size_t servers = 1;
};

class IsolatedExecutor : public runner::TestExecutor,
                         public runner::WorkerEnvironment,
                         public runner::WorkerNetwork {
public:
    explicit IsolatedExecutor(IsolationOptions options = IsolationOptions());
    ~IsolatedExecutor() override;

    // Starts the fork servers (run() does it on first use). False with `error` when the worker
    // program cannot be found or started.
    bool start(std::string& error);

    // spec.timeout > 0 bounds the whole worker (set-up, every repetition, tear-down).
    TestStatus run(const runner::TestSpec& spec, Test& self, TestResult& result) override;
    // Stops the running test's whole process tree; it is reported interrupted.
    void interrupt() override;
    std::unique_ptr<FixtureManager> makeFixture(const runner::FixtureSpec& spec,
                                                std::string& error) override;
    // Shares a fork server (the one the fewest open lanes use); ending the lane ends only what
    // it runs.
    std::unique_ptr<runner::TestExecutor> makeLane() override;
    // Given to every test this executor runs from now on.
    void setWorkerEnvironment(std::vector<std::string> variables) override {
        environment_ = std::move(variables);
    }
    // Every test this executor runs from now on runs in `network` (a lane's suite's).
    void setWorkerNetwork(std::shared_ptr<const platform::PrivateNetwork> network) override {
        network_ = std::move(network);
    }

    // Ends the fork server and every process the run started. The destructor does it too.
    void shutdown();

private:
    // A fork server and how many open lanes fork from it (makeLane picks the least used).
    struct ServerSlot {
        std::shared_ptr<ForkServer> server = std::make_shared<ForkServer>();
        std::atomic<std::size_t> lanes{0};
    };

    // A lane: forks from `slot`'s server, which it counts in while it is open.
    IsolatedExecutor(IsolationOptions options, std::shared_ptr<ServerSlot> slot);
    // wakeRead_/wakeWrite_, both non-blocking.
    void openWakePipe();

    IsolationOptions options_;
    std::shared_ptr<ForkServer> server_;              // where this executor's workers fork
    std::vector<std::shared_ptr<ServerSlot>> slots_;  // the servers it started (none: a lane)
    std::shared_ptr<ServerSlot> laneSlot_;            // a lane's server, counted in
    platform::FileDescriptor wakeRead_, wakeWrite_;   // interrupt() -> run()
    std::atomic<bool> interrupted_{false};
    std::vector<std::string> environment_;
    std::shared_ptr<const platform::PrivateNetwork> network_;
};

}  // namespace isolation
}  // namespace robottestingframework
