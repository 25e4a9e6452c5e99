#include <robottestingframework/TestResult.h>

#include <robottestingframework/TestSuite.h>

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

RunEvent eventOf(ResultEvent::Kind kind, const Test* test, TestMessage msg = TestMessage()) {
    RunEvent event;
    event.data.kind = kind;
    event.data.message = std::move(msg);
    event.test = test;
    return event;
}

}  // namespace

using Kind = ResultEvent::Kind;

void TestResult::addReport(const Test* test, TestMessage msg) {
    publish(eventOf(Kind::Report, test, bounded(std::move(msg))));
}

void TestResult::addError(const Test* test, TestMessage msg) {
    publish(eventOf(Kind::Error, test, bounded(std::move(msg))));
}

void TestResult::addFailure(const Test* test, TestMessage msg) {
    publish(eventOf(Kind::Failure, test, bounded(std::move(msg))));
}

void TestResult::startTest(const Test* test) {
    publish(eventOf(Kind::StartTest, test));
}

void TestResult::endTest(const Test* test) {
    publish(eventOf(Kind::EndTest, test));
}

void TestResult::startTestSuite(const TestSuite* suite) {
    RunEvent event = eventOf(Kind::StartSuite, suite);
    event.suite = suite;
    publish(event);
}

void TestResult::endTestSuite(const TestSuite* suite) {
    RunEvent event = eventOf(Kind::EndSuite, suite);
    event.suite = suite;
    publish(event);
}

void TestResult::startTestRunner() {
    publish(eventOf(Kind::StartRunner, nullptr));
}

void TestResult::endTestRunner() {
    publish(eventOf(Kind::EndRunner, nullptr));
}

void TestResult::addCheck(const Test* test, TestMessage msg, bool passed) {
    RunEvent event = eventOf(Kind::Check, test, bounded(std::move(msg)));
    event.data.passed = passed;
    publish(event);
}

void TestResult::addSkipped(const Test* test, TestMessage reason) {
    publish(eventOf(Kind::Skipped, test, bounded(std::move(reason))));
}

void TestResult::addCrash(const Test* test, TestMessage msg) {
    publish(eventOf(Kind::Crash, test, bounded(std::move(msg))));
}

void TestResult::addTimeout(const Test* test, TestMessage msg) {
    publish(eventOf(Kind::Timeout, test, bounded(std::move(msg))));
}

void TestResult::retryTest(const Test* test, TestMessage msg) {
    publish(eventOf(Kind::Retry, test, bounded(std::move(msg))));
}

void TestResult::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    RunEvent event = eventOf(Kind::Repetition, test);
    event.data.repetition = index;
    event.data.repetitions = count;
    publish(event);
}

void TestResult::addMeasurement(const Test* test, const Measurement& measurement, bool passed) {
    RunEvent event =
        eventOf(Kind::Measurement, test, TestMessage(describeMeasurement(measurement)));
    event.data.passed = passed;
    event.data.measurement = std::make_shared<const Measurement>(measurement);
    publish(event);
}

void TestResult::addAttachment(const Test* test, const Attachment& attachment) {
    RunEvent event = eventOf(Kind::Attachment, test, TestMessage(describeAttachment(attachment)));
    event.data.attachment = std::make_shared<const Attachment>(attachment);
    publish(event);
}

void TestResult::addInterrupted(const Test* test, TestMessage msg) {
    publish(eventOf(Kind::Interrupted, test, bounded(std::move(msg))));
}

void TestResult::addOutput(const Test* test, const std::string& text) {
    publish(eventOf(Kind::Output, test, TestMessage(text)));
}

void TestResult::renameTest(const Test* test, const std::string& name) {
    publish(eventOf(Kind::Rename, test, TestMessage(name)));
}

}  // namespace robottestingframework
