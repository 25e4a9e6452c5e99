// How a test or a fixture is run: in the runner's process, or in a worker process. The rest of
// the runner does not know which.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/Test.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestStatus.h>

#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace platform {
class PrivateNetwork;  // platform/private_network.h
}  // namespace platform
namespace runner {

// A fixture handle whose set-up or check in progress can be cut short when the run is
// interrupted (Ctrl-C). A tear-down is never cut short: it must run. Thread-safe.
class InterruptibleFixture {
public:
    virtual ~InterruptibleFixture() = default;
    virtual void interruptCall() = 0;
};

// Something that starts worker processes and can hand them extra environment variables
// ("NAME=VALUE"), e.g. the resource items the scheduler gave a suite (RTF_RESOURCE_<POOL>).
class WorkerEnvironment {
public:
    virtual ~WorkerEnvironment() = default;
    virtual void setWorkerEnvironment(std::vector<std::string> variables) = 0;
};

// Something that starts worker processes and can put them in a suite's private network
// (<suite network="private">): each worker joins it before it loads anything. nullptr: the
// machine's network.
class WorkerNetwork {
public:
    virtual ~WorkerNetwork() = default;
    virtual void setWorkerNetwork(std::shared_ptr<const platform::PrivateNetwork> network) = 0;
};

class TestExecutor {
public:
    virtual ~TestExecutor() = default;
    // Runs `spec`, sending its events to `result` about `self` (a stand-in Test the executor may
    // rename to the name the test reports): exactly one startTest and one endTest, whatever
    // happens. Returns the test's final state.
    virtual TestStatus run(const TestSpec& spec, Test& self, TestResult& result) = 0;
    // Stops the running test as soon as possible. Thread-safe; a no-op when nothing runs.
    virtual void interrupt() = 0;

    // Makes the fixture manager `spec` describes. Its setup/check/tearDown may run elsewhere
    // (a worker process) — the returned object is the runner's handle on it. nullptr and
    // `error` set when it cannot be made.
    virtual std::unique_ptr<FixtureManager> makeFixture(const FixtureSpec& spec,
                                                        std::string& error) = 0;
    // Another executor sharing this one's workers, whose run() and interrupt() may be called
    // while this one (or another lane) runs a test: one per suite running at the same time.
    // nullptr when tests cannot run side by side (in the runner's process).
    virtual std::unique_ptr<TestExecutor> makeLane() { return nullptr; }
};

}  // namespace runner
}  // namespace robottestingframework
