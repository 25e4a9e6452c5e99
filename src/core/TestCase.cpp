#include <robottestingframework/TestCase.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <iterator>
#include <memory>
#include <mutex>
#include <typeinfo>
#include <vector>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/Exception.h>
#include <robottestingframework/TestResult.h>

#include "core/not_run_reasons.h"
#include "type_name.h"

namespace robottestingframework {

namespace {

// The test the calling thread runs, if it runs one; otherwise the test started last among those
// running in the process, so helper threads a test starts report to it too. A list, not one
// pointer: runs in several threads of one process (TestRunner in two threads, the scheduler's
// lanes) end in any order, and each must take out only itself.
thread_local TestCase* threadTest = nullptr;
std::mutex runningMutex;
std::vector<TestCase*> runningTests;

void startRunning(TestCase* test) {
    std::lock_guard<std::mutex> lock(runningMutex);
    runningTests.push_back(test);
}

void stopRunning(TestCase* test) {
    std::lock_guard<std::mutex> lock(runningMutex);
    auto found = std::find(runningTests.rbegin(), runningTests.rend(), test);
    if (found != runningTests.rend()) {
        runningTests.erase(std::next(found).base());
    }
}

}  // namespace

TestCase::TestCase(std::string name, std::string param) : Test(std::move(name)), param_(param) {}

TestCase::~TestCase() {
    if (threadTest == this) {
        threadTest = nullptr;
    }
    std::lock_guard<std::mutex> lock(runningMutex);
    runningTests.erase(std::remove(runningTests.begin(), runningTests.end(), this),
                       runningTests.end());
}

bool TestCase::setup(int /*argc*/, char** /*argv*/) {
    return true;
}

void TestCase::tearDown() {}

TestCase* TestCase::current() {
    if (threadTest != nullptr) {
        return threadTest;
    }
    std::lock_guard<std::mutex> lock(runningMutex);
    return runningTests.empty() ? nullptr : runningTests.back();
}

void TestCase::interrupt() {
    interrupted_ = true;
}

bool TestCase::succeeded() const {
    return successful_;
}

void TestCase::failed() {
    successful_ = false;
}

TestResult* TestCase::getResult() {
    return result_;
}

namespace {

// Runs one step of the test, turning whatever it throws into the event it means. Returns
// false when the step threw.
template <typename Step>
bool guarded(TestCase& test, TestResult& result, Step step) {
    try {
        step();
        return true;
    } catch (const TestCriticalErrorException& e) {
        result.addError(&test, e.message());
        test.setCriticalError(e.message());
    } catch (const TestErrorException& e) {
        result.addError(&test, e.message());
    } catch (const TestFailureException& e) {
        result.addFailure(&test, e.message());
    } catch (const Exception& e) {
        result.addError(&test, e.message());
    } catch (const std::exception& e) {
        result.addError(&test, TestMessage("unhandled exception: " + std::string(e.what()),
                                           typeName(typeid(e))));
    } catch (...) {
        result.addError(&test, TestMessage("unhandled exception of unknown type"));
    }
    test.failed();
    return false;
}

}  // namespace

void TestCase::run(TestResult& result) {
    successful_ = true;
    failureReported_ = false;
    clearCriticalError();
    result_ = &result;
    TestCase* const previous = threadTest;
    threadTest = this;
    startRunning(this);

    result.startTest(this);
    reportRenamesTo(&result);
    bool reported = false;  // a failure or error event was sent by this function
    if (interrupted_) {
        result.addInterrupted(this, TestMessage("interrupted before it started"));
    } else {
        ArgumentVector args(getName(), getParam());
        bool up = false;
        if (guarded(*this, result, [&] { up = setup(args.argc(), args.argv()); })) {
            if (!up) {
                result.addError(this, TestMessage("setup failed", "test " + getName()));
                successful_ = false;
                reported = true;
            }
        } else {
            reported = true;
        }
        if (up) {
            const unsigned int count = repetition_ == 0 ? 1 : repetition_;
            for (unsigned int k = 1; k <= count && !interrupted_; ++k) {
                if (count > 1) {
                    result.startRepetition(this, k, count);
                }
                if (!guarded(*this, result, [this] { run(); })) {
                    reported = true;
                    break;
                }
            }
            if (!guarded(*this, result, [this] { tearDown(); })) {
                reported = true;
            }
        }
        if (interrupted_) {
            result.addInterrupted(this, TestMessage(notrun::stoppedWhileRunning));
            successful_ = false;
            reported = true;
        }
    }
    // failed() alone leaves no message; say so, or the outputs would show it passed.
    if (!successful_ && !reported && !failureReported_) {
        result.addFailure(this, TestMessage("the test marked itself failed"));
    }
    reportRenamesTo(nullptr);
    result.endTest(this);

    stopRunning(this);
    threadTest = previous;
    result_ = nullptr;
    interrupted_ = false;
}

}  // namespace robottestingframework
