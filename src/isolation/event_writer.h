// In a worker: a listener that sends every event of the test (or fixture) to the runner as
// wire records, whatever its kind. Thread-safe: a fixture may report collapse from any thread.
#pragma once

#include <mutex>
#include <string>

#include <robottestingframework/TestListener.h>

#include "isolation/wire_format.h"

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
    // Sends `event` (made by name, core/events.h) about `test`: what the worker itself says.
    void sendEvent(const ResultEvent& event, const Test* test);

    void onEvent(const RunEvent& event) override;

private:
    int fd_;
    std::mutex mutex_;
    std::string held_;
};

}  // namespace isolation
}  // namespace robottestingframework
