#include <robottestingframework/TestResult.h>

#include <robottestingframework/TestSuite.h>

#include <algorithm>
#include <string>
#include <utility>

#include "core/events.h"

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

// Every event is delivered to all listeners before the next one starts, whatever thread
// sends it; the mutex is recursive because a listener may report in turn.
void TestResult::publish(const RunEvent& event) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    for (TestListener* listener : listeners_) {
        listener->onEvent(event);
    }
}

namespace {

RunEvent eventOf(ResultEvent data, const Test* test) {
    return RunEvent{std::move(data), test};
}

}  // namespace

void TestResult::addReport(const Test* test, TestMessage msg) {
    publish(eventOf(events::report(bounded(std::move(msg))), test));
}

void TestResult::addError(const Test* test, TestMessage msg) {
    publish(eventOf(events::error(bounded(std::move(msg))), test));
}

void TestResult::addFailure(const Test* test, TestMessage msg) {
    publish(eventOf(events::failure(bounded(std::move(msg))), test));
}

void TestResult::startTest(const Test* test) {
    publish(eventOf(events::startTest(), test));
}

void TestResult::endTest(const Test* test) {
    publish(eventOf(events::endTest(), test));
}

void TestResult::startTestSuite(const TestSuite* suite) {
    RunEvent event = eventOf(events::startSuite(), suite);
    event.suite = suite;
    publish(event);
}

void TestResult::endTestSuite(const TestSuite* suite) {
    RunEvent event = eventOf(events::endSuite(), suite);
    event.suite = suite;
    publish(event);
}

void TestResult::startTestRunner() {
    publish(eventOf(events::startRunner(), nullptr));
}

void TestResult::endTestRunner() {
    publish(eventOf(events::endRunner(), nullptr));
}

void TestResult::addCheck(const Test* test, TestMessage msg, bool passed) {
    publish(eventOf(events::check(bounded(std::move(msg)), passed), test));
}

void TestResult::addSkipped(const Test* test, TestMessage reason) {
    publish(eventOf(events::skipped(bounded(std::move(reason))), test));
}

void TestResult::addCrash(const Test* test, TestMessage msg) {
    publish(eventOf(events::crash(bounded(std::move(msg))), test));
}

void TestResult::addTimeout(const Test* test, TestMessage msg) {
    publish(eventOf(events::timeout(bounded(std::move(msg))), test));
}

void TestResult::retryTest(const Test* test, TestMessage msg) {
    publish(eventOf(events::retry(bounded(std::move(msg))), test));
}

void TestResult::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    publish(eventOf(events::repetition(index, count), test));
}

void TestResult::addMeasurement(const Test* test, const Measurement& measurement, bool passed) {
    publish(eventOf(events::measurement(std::make_shared<const Measurement>(measurement), passed,
                                        TestMessage(describeMeasurement(measurement))),
                    test));
}

void TestResult::addAttachment(const Test* test, const Attachment& attachment) {
    publish(eventOf(events::attachment(std::make_shared<const Attachment>(attachment),
                                       TestMessage(describeAttachment(attachment))),
                    test));
}

void TestResult::addInterrupted(const Test* test, TestMessage msg) {
    publish(eventOf(events::interrupted(bounded(std::move(msg))), test));
}

void TestResult::addOutput(const Test* test, const std::string& text) {
    publish(eventOf(events::output(text), test));
}

void TestResult::renameTest(const Test* test, const std::string& name) {
    publish(eventOf(events::rename(name), test));
}

}  // namespace robottestingframework
