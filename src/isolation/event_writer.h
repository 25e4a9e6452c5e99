// In a worker: a listener that sends every event of the test (or fixture) to the runner as
// wire records. Thread-safe: a fixture may report collapse from any thread.
#pragma once

#include <mutex>

#include <robottestingframework/TestListener.h>

#include "wire_format.h"

namespace robottestingframework {
namespace isolation {

class EventWriter : public TestListener {
public:
    explicit EventWriter(int fd) : fd_(fd) {}

    // Sends one record (with any held one before it); false when the runner is gone.
    bool send(const WireRecord& record);
    // Holds a record until the next send: for records whose loss in a crash costs nothing
    // (the runner frames the test itself), so that they share a write with the next one.
    void hold(const WireRecord& record);
    void sendEvent(ResultEvent::Kind kind, const Test* test, const TestMessage& msg,
                   bool passed = true);

    void addReport(const Test* test, TestMessage msg) override;
    void addError(const Test* test, TestMessage msg) override;
    void addFailure(const Test* test, TestMessage msg) override;
    void startTest(const Test* test) override;
    void endTest(const Test* test) override;
    void addCheck(const Test* test, TestMessage msg, bool passed) override;
    void addSkipped(const Test* test, TestMessage reason) override;
    void addCrash(const Test* test, TestMessage msg) override;
    void addTimeout(const Test* test, TestMessage msg) override;
    void addInterrupted(const Test* test, TestMessage msg) override;
    void addOutput(const Test* test, const std::string& text) override;
    void renameTest(const Test* test, const std::string& name) override;
    void startRepetition(const Test* test, unsigned int index, unsigned int count) override;

private:
    int fd_;
    std::mutex mutex_;
    std::string held_;
};

}  // namespace isolation
}  // namespace robottestingframework
