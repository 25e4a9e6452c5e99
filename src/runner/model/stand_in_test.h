// The runner's stand-in for one test of a suite: what the suite runs and the events are about.
// The real test case is made by the executor when the stand-in runs (maybe in another process),
// so nothing outside the executor ever holds a pointer to it.
#pragma once

#include <atomic>

#include <robottestingframework/Test.h>
#include <robottestingframework/TestStatus.h>

#include "runner/model/suite_model.h"
#include "runner/model/test_executor.h"

namespace robottestingframework {
namespace runner {

class PluginTest : public Test {
public:
    // `spec` and `executor` must outlive the stand-in.
    PluginTest(const TestSpec& spec, TestExecutor& executor);

    // A test that fails runs again up to `retries` times (--retries); 0: once.
    void setRetries(unsigned int retries) { retries_ = retries; }

    void run(TestResult& result) override;
    void interrupt() override;
    bool succeeded() const override { return !isFailure(status_); }

    const TestSpec& spec() const { return spec_; }
    // The final state; meaningful once ran() (a test skipped before it ran never ran).
    TestStatus status() const { return status_; }
    bool ran() const { return ran_; }

    // The name shown before the test case reports its own: name="..." or the plug-in's file.
    static std::string displayName(const TestSpec& spec);

private:
    const TestSpec& spec_;
    TestExecutor& executor_;
    // Read by the gate from other suites' threads while this one runs.
    std::atomic<TestStatus> status_{TestStatus::Passed};
    std::atomic<bool> ran_{false};
    unsigned int retries_ = 0;
    std::atomic<bool> interrupted_{false};
};

}  // namespace runner
}  // namespace robottestingframework
