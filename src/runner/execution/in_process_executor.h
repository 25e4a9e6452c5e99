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

    // The file and type of the plug-in `spec` names (languages::locatePlugin), found once for
    // the tests that name it through the same strings, as a suite's tests of one plug-in do.
    bool locate(const TestSpec& spec, std::string& error);
    struct Located {
        SharedString plugin, path, type, file;  // what the last spec named
        std::string foundPath, foundType;       // what it was found to be
        bool valid = false;
    };
    Located located_;

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
