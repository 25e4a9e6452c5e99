#include <robottestingframework/TestRunner.h>

#include <algorithm>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "core/not_run_reasons.h"

namespace robottestingframework {

TestRunner::TestRunner() = default;

TestRunner::~TestRunner() = default;

void TestRunner::addTest(Test* test) {
    if (test != nullptr) {
        tests_.push_back(test);
    }
}

void TestRunner::removeTest(Test* test) {
    tests_.erase(std::remove(tests_.begin(), tests_.end(), test), tests_.end());
}

void TestRunner::reset() {
    tests_.clear();
}

void TestRunner::interrupt() {
    interrupted_ = true;
    std::lock_guard<std::mutex> lock(mutex_);
    if (current_ != nullptr) {
        current_->interrupt();
    }
}

namespace {

void reportNotRun(TestResult& result, Test* test, const TestMessage& reason, bool interrupted) {
    if (auto* suite = dynamic_cast<TestSuite*>(test)) {
        suite->reportNotRun(result, reason, interrupted);
        return;
    }
    result.startTest(test);
    if (interrupted) {
        result.addInterrupted(test, reason);
    } else {
        result.addSkipped(test, reason);
    }
    result.endTest(test);
}

}  // namespace

void TestRunner::run(TestResult& result) {
    result.startTestRunner();
    for (Test* test : tests_) {
        if (interrupted_) {
            reportNotRun(result, test, TestMessage(notrun::interrupted), true);
            continue;
        }
        TestMessage reason;
        if (gate_ != nullptr && gate_->skip(test, reason)) {
            reportNotRun(result, test, reason, false);
            continue;
        }
        auto* suite = dynamic_cast<TestSuite*>(test);
        if (suite != nullptr && gate_ != nullptr) {
            suite->setGate(gate_);
        }
        bool started = false;
        {
            // The same lock as interrupt(): an interrupt is either seen here or reaches the test.
            std::lock_guard<std::mutex> lock(mutex_);
            if (!interrupted_) {
                current_ = test;
                started = true;
            }
        }
        if (!started) {
            reportNotRun(result, test, TestMessage(notrun::interrupted), true);
            continue;
        }
        test->run(result);
        std::lock_guard<std::mutex> lock(mutex_);
        current_ = nullptr;
    }
    result.endTestRunner();
}

}  // namespace robottestingframework
