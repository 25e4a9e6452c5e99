// Runs tests and suites one after the other, framed by startTestRunner/endTestRunner.
#pragma once

#include <atomic>
#include <mutex>
#include <vector>

#include <robottestingframework/Test.h>
#include <robottestingframework/TestGate.h>
#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestResult.h>  // RTF 2.x users rely on it coming along

namespace robottestingframework {

class TestResult;

class TestRunner {
public:
    TestRunner();
    virtual ~TestRunner();

    // Tests are not owned.
    void addTest(Test* test);
    void removeTest(Test* test);
    void reset();

    void run(TestResult& result);
    // Stops the running test and reports the ones not yet run as interrupted. Thread-safe.
    void interrupt();
    bool interrupted() const { return interrupted_; }

    // Beyond RTF 2.x: consulted before each test and passed on to suites (see TestGate).
    void setGate(TestGate* gate) { gate_ = gate; }

private:
    std::vector<Test*> tests_;
    std::atomic<bool> interrupted_{false};
    TestGate* gate_ = nullptr;
    std::mutex mutex_;
    Test* current_ = nullptr;
};

}  // namespace robottestingframework
