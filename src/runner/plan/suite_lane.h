// The executor a suite's tests run through. Alone (-j1, the library's TestRunner) it is the
// run's executor; when the scheduler runs suites side by side it opens a lane of its own
// (TestExecutor::makeLane) for as long as the suite runs, so that interrupting or ending one
// suite's test never touches another's.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "runner/model/test_executor.h"

namespace robottestingframework {
namespace runner {

class SuiteLane : public TestExecutor {
public:
    explicit SuiteLane(TestExecutor& base) : base_(base) {}

    // Before the suite runs (on the scheduler's thread): a lane of its own when the executor
    // has lanes, with `environment` ("NAME=VALUE") for its workers, and its private network
    // (nullptr: the machine's).
    void open(std::vector<std::string> environment,
              std::shared_ptr<const platform::PrivateNetwork> network = nullptr);
    // After the suite ran: back to the run's executor.
    void close();

    TestStatus run(const TestSpec& spec, Test& self, TestResult& result) override {
        return current().run(spec, self, result);
    }
    void interrupt() override;
    std::unique_ptr<FixtureManager> makeFixture(const FixtureSpec& spec,
                                                std::string& error) override {
        return base_.makeFixture(spec, error);
    }

private:
    TestExecutor& current();

    TestExecutor& base_;
    std::mutex mutex_;  // interrupt() comes from other threads
    std::unique_ptr<TestExecutor> own_;
};

}  // namespace runner
}  // namespace robottestingframework
