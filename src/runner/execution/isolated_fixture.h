// The runner's handle on a fixture manager that lives in a worker process for the whole suite.
// setup/check/tearDown are calls to the worker, each bounded in time; a worker that crashes or
// hangs makes the call fail with the reason (a TestErrorException, which the suite reports
// and hands on to the tests it skips), and one that dies between calls, or reports a collapse
// from any of its threads, collapses the fixture through the dispatcher.
#pragma once

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <robottestingframework/FixtureManager.h>

#include "isolation/fork_server_client.h"
#include "isolation/wire_format.h"
#include "isolation/worker_process.h"
#include "platform/file_descriptor.h"
#include "runner/execution/isolated_executor.h"
#include "runner/model/test_executor.h"

namespace robottestingframework {
namespace isolation {

class IsolatedFixture : public FixtureManager,
                        public runner::InterruptibleFixture,
                        public runner::WorkerEnvironment,
                        public runner::WorkerNetwork {
public:
    IsolatedFixture(std::shared_ptr<ForkServer> server, WorkRequest request,
                    IsolationOptions options);
    ~IsolatedFixture() override;

    bool setup(int argc, char** argv) override;
    bool check() override;
    void tearDown() override;
    // A setup or check in progress fails as interrupted (the worker is stopped).
    void interruptCall() override;
    // Given to the worker when it starts (at the first call).
    void setWorkerEnvironment(std::vector<std::string> variables) override {
        request_.variables = std::move(variables);
    }
    // The worker joins it when it starts (at the first call).
    void setWorkerNetwork(std::shared_ptr<const platform::PrivateNetwork> network) override {
        network_ = std::move(network);
    }

    // Why the last call failed (empty when it returned false without saying why).
    std::string failure() const { return failure_; }

private:
    bool call(const std::string& name, const std::string& payload);
    void watch();  // the reader thread: pumps the worker, never touches the result
    void flush();  // on the caller's thread: queued events and output to the result
    void kill();   // stops the worker's process tree (called with nothing locked)
    void waitDead(double seconds);

    std::shared_ptr<ForkServer> server_;
    WorkRequest request_;
    std::shared_ptr<const platform::PrivateNetwork> network_;
    IsolationOptions options_;
    std::unique_ptr<WorkerProcess> worker_;
    platform::FileDescriptor writer_;  // our end of the channel, for calls (main thread only)
    platform::FileDescriptor wakeRead_, wakeWrite_;
    std::thread reader_;
    pid_t pid_ = -1;

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<WireRecord> events_;
    std::string output_;
    bool replied_ = false;
    WireRecord reply_;
    bool dead_ = false;
    int status_ = 0;
    bool inCall_ = false;
    std::string callName_;      // the call in progress
    bool interrupted_ = false;  // interruptCall() during it
    bool quitting_ = false;
    std::string failure_;
    // Failed checks of its tear-down the suite did not take (FixtureEvents::fixtureCheckFailed
    // returned false): tearDown throws them (caller's thread only).
    std::string untakenChecks_;
};

}  // namespace isolation
}  // namespace robottestingframework
