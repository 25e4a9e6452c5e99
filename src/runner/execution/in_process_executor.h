// Runs tests and fixtures in the runner's own process (--isolation none), and what the C++
// library does without the runner. A crash here takes the run down; process isolation does not.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>

#include "languages/test_loader.h"
#include "runner/model/test_executor.h"

namespace robottestingframework {
namespace runner {

class InProcessExecutor : public TestExecutor {
public:
    InProcessExecutor();
    ~InProcessExecutor() override;

    TestStatus run(const TestSpec& spec, Test& self, TestResult& result) override;
    void interrupt() override;
    std::unique_ptr<FixtureManager> makeFixture(const FixtureSpec& spec,
                                                std::string& error) override;

private:
    class Relay;

    TestStatus notLoaded(const TestSpec& spec, Test& self, TestResult& result,
                         const std::string& reason);

    std::unique_ptr<Relay> relay_;
    TestResult relayed_;  // what the test case reports to: only the relay listens
    // The last test case made from each file. Each test gets a fresh object, but keeping the
    // previous one until the next is made keeps the library (or module) loaded: a suite of
    // many tests of one plug-in loads it once.
    std::unordered_map<std::string, std::unique_ptr<languages::LoadedTest>> loaded_;
    std::mutex mutex_;
    TestCase* running_ = nullptr;
};

}  // namespace runner
}  // namespace robottestingframework
