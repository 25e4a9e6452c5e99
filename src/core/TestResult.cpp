#include <robottestingframework/TestResult.h>

#include <algorithm>
#include <string>
#include <utility>

namespace robottestingframework {

namespace {

// A message or detail longer than this is cut, saying so: a test that reports megabytes can
// neither fill the memory of the runner nor break a worker's event stream (README: Output
// limits). The start is kept: it says what the message is about. Above the 64 KiB a TAP line
// of an exec test is cut to, so that such a line keeps its own note.
constexpr std::size_t maxMessageText = 128 * 1024;

std::string cut(const std::string& text) {
    return text.substr(0, maxMessageText) + " [... " +
           std::to_string(text.size() - maxMessageText) + " more bytes of this message dropped]";
}

TestMessage bounded(TestMessage msg) {
    if (msg.getMessage().size() > maxMessageText) {
        msg.setMessage(cut(msg.getMessage()));
    }
    if (msg.getDetail().size() > maxMessageText) {
        msg.setDetail(cut(msg.getDetail()));
    }
    return msg;
}

}  // namespace

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
    msg = bounded(std::move(msg));
    RTF_DISPATCH(addReport(test, msg))
}

void TestResult::addError(const Test* test, TestMessage msg) {
    msg = bounded(std::move(msg));
    RTF_DISPATCH(addError(test, msg))
}

void TestResult::addFailure(const Test* test, TestMessage msg) {
    msg = bounded(std::move(msg));
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
    msg = bounded(std::move(msg));
    RTF_DISPATCH(addCheck(test, msg, passed))
}

void TestResult::addSkipped(const Test* test, TestMessage reason) {
    reason = bounded(std::move(reason));
    RTF_DISPATCH(addSkipped(test, reason))
}

void TestResult::addCrash(const Test* test, TestMessage msg) {
    msg = bounded(std::move(msg));
    RTF_DISPATCH(addCrash(test, msg))
}

void TestResult::addTimeout(const Test* test, TestMessage msg) {
    msg = bounded(std::move(msg));
    RTF_DISPATCH(addTimeout(test, msg))
}

void TestResult::retryTest(const Test* test, TestMessage msg) {
    msg = bounded(std::move(msg));
    RTF_DISPATCH(retryTest(test, msg))
}

void TestResult::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    RTF_DISPATCH(startRepetition(test, index, count))
}

void TestResult::addInterrupted(const Test* test, TestMessage msg) {
    msg = bounded(std::move(msg));
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
