#include "isolation/event_relay.h"

namespace robottestingframework {
namespace isolation {

using Kind = ResultEvent::Kind;

bool relayEvent(const WireRecord& record, const Test* about, TestResult& result) {
    if (record.kind != WireKind::Event || isFrame(record.event)) {
        return false;
    }
    RunEvent event;
    event.data = eventOf(record);
    event.test = about;
    result.publish(event);
    return true;
}

void EventRelay::start() {
    if (!started_) {
        started_ = true;
        result_.startTest(&self_);
    }
}

void EventRelay::note(Kind kind, const TestMessage& message) {
    const TestStatus status = stateOf(kind);
    if (status > status_) {
        status_ = status;
    }
    if (isLastWords(kind)) {
        lastSaid_ = message.toString();
    }
}

void EventRelay::relay(const WireRecord& record) {
    if (record.kind == WireKind::Finished) {
        finished_ = true;
        return;
    }
    if (record.kind == WireKind::Described) {
        rename(record.name);
        self_.setDescription(record.message.getMessage());
        return;
    }
    if (record.kind == WireKind::CriticalError) {
        self_.setCriticalError(record.message);
        return;
    }
    if (record.kind != WireKind::Event || ended_) {
        return;
    }
    if (renamesTest(record.event)) {
        rename(record.message.getMessage());
        return;
    }
    if (startsRepetition(record.event)) {
        if (record.repetition == 0 || record.repetition > record.repetitions) {
            return;  // garbage from a broken worker: not a repetition
        }
        // A crash or timeout names the repetition it ended.
        repetition_ = repetitionMessage(record.repetition, record.repetitions).getMessage();
    }
    // The test's own name wins (a script may set it in setup).
    if (!record.name.empty() && record.name != self_.getName()) {
        rename(record.name);
    }
    if (startsTest(record.event)) {
        start();
        return;
    }
    if (endsTest(record.event)) {
        return;  // held back: the runner may still have something to say (a crash after it)
    }
    start();
    if (relayEvent(record, &self_, result_)) {
        note(record.event, record.message);
    }
}

void EventRelay::rename(const std::string& name) {
    if (name.empty() || name == self_.getName()) {
        return;
    }
    self_.setName(name);
    // Before its start the listeners take the name from startTest.
    if (started_ && !ended_) {
        result_.renameTest(&self_, name);
    }
}

void EventRelay::add(const ResultEvent& event) {
    start();
    relayEvent(eventRecord(event, std::string()), &self_, result_);
    note(event.kind, event.message);
}

void EventRelay::end(const std::string& output) {
    start();
    if (!output.empty()) {
        result_.addOutput(&self_, output);
    }
    if (!ended_) {
        ended_ = true;
        result_.endTest(&self_);
    }
}

}  // namespace isolation
}  // namespace robottestingframework
