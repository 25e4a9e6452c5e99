#include "event_writer.h"

#include <robottestingframework/Test.h>

#include "file_descriptor.h"

namespace robottestingframework {
namespace isolation {

using Kind = ResultEvent::Kind;

bool EventWriter::send(const WireRecord& record) {
    std::string bytes = encode(record);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!held_.empty()) {
        bytes.insert(0, held_);
        held_.clear();
    }
    return platform::writeAll(fd_, bytes);
}

void EventWriter::hold(const WireRecord& record) {
    std::lock_guard<std::mutex> lock(mutex_);
    encode(record, held_);
}

void EventWriter::sendEvent(Kind kind, const Test* test, const TestMessage& msg, bool passed) {
    WireRecord record;
    record.kind = WireKind::Event;
    record.event = kind;
    record.name = test != nullptr ? test->getName() : std::string();
    record.message = msg;
    record.flag = passed;
    send(record);
}

void EventWriter::addReport(const Test* test, TestMessage msg) {
    sendEvent(Kind::Report, test, msg);
}
void EventWriter::addError(const Test* test, TestMessage msg) {
    sendEvent(Kind::Error, test, msg);
}
void EventWriter::addFailure(const Test* test, TestMessage msg) {
    sendEvent(Kind::Failure, test, msg);
}
void EventWriter::startTest(const Test* test) {
    sendEvent(Kind::StartTest, test, TestMessage());
}
void EventWriter::endTest(const Test* test) {
    // The runner holds endTest back until the worker finished anyway.
    WireRecord record;
    record.event = Kind::EndTest;
    record.name = test != nullptr ? test->getName() : std::string();
    hold(record);
}
void EventWriter::addCheck(const Test* test, TestMessage msg, bool passed) {
    sendEvent(Kind::Check, test, msg, passed);
}
void EventWriter::addSkipped(const Test* test, TestMessage reason) {
    sendEvent(Kind::Skipped, test, reason);
}
void EventWriter::addCrash(const Test* test, TestMessage msg) {
    sendEvent(Kind::Crash, test, msg);
}
void EventWriter::addTimeout(const Test* test, TestMessage msg) {
    sendEvent(Kind::Timeout, test, msg);
}
void EventWriter::addInterrupted(const Test* test, TestMessage msg) {
    sendEvent(Kind::Interrupted, test, msg);
}
void EventWriter::addOutput(const Test* test, const std::string& text) {
    sendEvent(Kind::Output, test, TestMessage(text));
}
void EventWriter::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    WireRecord record;
    record.kind = WireKind::Repetition;
    record.name = test != nullptr ? test->getName() : std::string();
    record.message = repetitionMessage(index, count);
    record.number = static_cast<std::int64_t>((static_cast<std::uint64_t>(count) << 32) | index);
    send(record);
}
void EventWriter::renameTest(const Test* test, const std::string& name) {
    sendEvent(Kind::Rename, test, TestMessage(name));
}

}  // namespace isolation
}  // namespace robottestingframework
