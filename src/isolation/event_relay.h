// In the runner: turns a worker's records back into TestResult events about the runner's
// stand-in for the test, keeping the contract of exactly one startTest and one endTest.
#pragma once

#include <string>

#include <robottestingframework/Test.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestStatus.h>

#include "isolation/wire_format.h"

namespace robottestingframework {
namespace isolation {

// Sends one event record to `result` about `about`. Start/end and runner/suite events are
// not sent (the caller frames the test). Returns false for records that are not events.
bool relayEvent(const WireRecord& record, const Test* about, TestResult& result);

class EventRelay {
public:
    EventRelay(Test& self, TestResult& result) : self_(self), result_(result) {}

    // A record from the worker: events go to the result (the test renamed to the name it
    // reports), a critical error is set on the stand-in.
    void relay(const WireRecord& record);
    // What the runner adds itself: a crash, a timeout, an interruption, an error.
    // Made by name (core/events.h: events::crash(...), ...).
    void add(const ResultEvent& event);
    // Sends the output tail (if any) and the one endTest.
    void end(const std::string& output);

    bool finished() const { return finished_; }
    TestStatus status() const { return status_; }
    // The last thing the test reported (a report, check, failure or error), for the message
    // of a crash or timeout.
    const std::string& lastSaid() const { return lastSaid_; }
    // "repetition k/N" while a test with several repetitions runs, else empty.
    const std::string& repetition() const { return repetition_; }

    // Sends the one startTest now (else the first event sends it).
    void start();

private:
    void note(ResultEvent::Kind kind, const TestMessage& message);
    // The stand-in takes the test's new name, and the listeners hear of it as an event.
    void rename(const std::string& name);

    Test& self_;
    TestResult& result_;
    bool started_ = false;
    bool ended_ = false;
    bool finished_ = false;
    TestStatus status_ = TestStatus::Passed;
    std::string lastSaid_;
    std::string repetition_;
};

}  // namespace isolation
}  // namespace robottestingframework
