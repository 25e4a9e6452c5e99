// A single test: set up, run (possibly several times), torn down. Users derive from it.
#pragma once

#include <atomic>
#include <string>

#include <robottestingframework/Test.h>
#include <robottestingframework/TestResult.h>  // RTF 2.x users rely on it coming along

namespace robottestingframework {

class TestResult;

class TestCase : public Test {
public:
    explicit TestCase(std::string name, std::string param = "");
    ~TestCase() override;

    // argv[0] is the test's name; the rest is the param string split by RTF 2.x's rules
    // (ArgumentVector: at spaces, "..." grouping words).
    // Returning false is an error: run() is not called, tearDown() is not called.
    virtual bool setup(int argc, char** argv);
    virtual void tearDown();
    virtual void run() = 0;

    // Sends startTest, set-up, getRepetition() runs, tear-down and endTest to `result`.
    void run(TestResult& result) override;
    void interrupt() override;
    bool succeeded() const override;

    // Marks the test failed without stopping it.
    void failed();
    // The result the test is reporting to while it runs, nullptr otherwise.
    TestResult* getResult();

    void setParam(const std::string& param) { param_ = param; }
    std::string getParam() const { return param_; }
    void setEnvironment(const std::string& environment) { environment_ = environment; }
    std::string getEnvironment() const { return environment_; }
    void setRepetition(unsigned int repetition) { repetition_ = repetition; }
    unsigned int getRepetition() const { return repetition_; }

    // True once interrupt() was called during the current run.
    bool interrupted() const { return interrupted_; }

    // The test case whose setup/run/tearDown is executing on this process, if any. The
    // assertion macros report to it, so they also work from helper functions and scripts.
    static TestCase* current();

private:
    friend class Asserter;  // marks a failure as already reported

    std::string param_;
    std::string environment_;
    unsigned int repetition_ = 1;
    // Helper threads of a test may report and mark it failed while it runs.
    std::atomic<bool> successful_{true};
    std::atomic<bool> failureReported_{false};
    std::atomic<bool> interrupted_{false};
    std::atomic<TestResult*> result_{nullptr};
};

}  // namespace robottestingframework
