#include <robottestingframework/TestResult.h>

#include <algorithm>

namespace robottestingframework {

// Every event is delivered to all listeners before the next one starts, whatever thread
// sends it; the mutex is recursive because a listener may report in turn.
#define RTF_DISPATCH(call)                              \
    std::lock_guard<std::recursive_mutex> lock(mutex_); \
    for (TestListener * listener : listeners_) {        \
        listener->call;                                 \
    }

void TestResult::addListener(TestListener* listener) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    if (listener && std::find(listeners_.begin(), listeners_.end(), listener) == listeners_.end()) {
        listeners_.push_back(listener);
    }
}

void TestResult::removeListener(TestListener* listener) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    listeners_.erase(std::remove(listeners_.begin(), listeners_.end(), listener), listeners_.end());
}

void TestResult::addReport(const Test* test, TestMessage msg) {
    RTF_DISPATCH(addReport(test, msg))
}

void TestResult::addError(const Test* test, TestMessage msg) {
    RTF_DISPATCH(addError(test, msg))
}

void TestResult::addFailure(const Test* test, TestMessage msg) {
    RTF_DISPATCH(addFailure(test, msg))
}

void TestResult::startTest(const Test* test) {
    RTF_DISPATCH(startTest(test))
}

void TestResult::endTest(const Test* test) {
    RTF_DISPATCH(endTest(test))
}

void TestResult::startTestSuite(const TestSuite* suite) {
    RTF_DISPATCH(startTestSuite(suite))
}

void TestResult::endTestSuite(const TestSuite* suite) {
    RTF_DISPATCH(endTestSuite(suite))
}

void TestResult::startTestRunner() {
    RTF_DISPATCH(startTestRunner())
}

void TestResult::endTestRunner() {
    RTF_DISPATCH(endTestRunner())
}

void TestResult::addCheck(const Test* test, TestMessage msg, bool passed) {
    RTF_DISPATCH(addCheck(test, msg, passed))
}

void TestResult::addSkipped(const Test* test, TestMessage reason) {
    RTF_DISPATCH(addSkipped(test, reason))
}

void TestResult::addCrash(const Test* test, TestMessage msg) {
    RTF_DISPATCH(addCrash(test, msg))
}

void TestResult::addTimeout(const Test* test, TestMessage msg) {
    RTF_DISPATCH(addTimeout(test, msg))
}

void TestResult::retryTest(const Test* test, TestMessage msg) {
    RTF_DISPATCH(retryTest(test, msg))
}

void TestResult::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    RTF_DISPATCH(startRepetition(test, index, count))
}

void TestResult::addInterrupted(const Test* test, TestMessage msg) {
    RTF_DISPATCH(addInterrupted(test, msg))
}

void TestResult::addOutput(const Test* test, const std::string& text) {
    RTF_DISPATCH(addOutput(test, text))
}

void TestResult::renameTest(const Test* test, const std::string& name) {
    RTF_DISPATCH(renameTest(test, name))
}

#undef RTF_DISPATCH

}  // namespace robottestingframework
