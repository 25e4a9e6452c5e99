// What a suite running on a thread of its own reports, kept in order until the scheduler's
// thread hands it on: the listeners of the run (console, collector, reporters, web page) get
// every event from that one thread, each suite's events in the order they happened. Events
// are kept as data, whatever their kind.
#pragma once

#include <functional>
#include <mutex>
#include <vector>

#include <robottestingframework/RunEvent.h>
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResult.h>

namespace robottestingframework {
namespace runner {

class SuiteEvents : public TestListener {
public:
    using Event = RunEvent;

    // `wake`: called (on the reporting thread) to wake the scheduler: once per batch of events,
    // and, while a test runs, not before it ends (see kLookMs).
    explicit SuiteEvents(std::function<void()> wake) : wake_(std::move(wake)) {}

    // How long the scheduler may leave events of a running test kept (its start, its checks):
    // it looks this often while suites run. Waking it for each one cost two thread switches
    // and five system calls a test, for a line no one can read at a thousand tests a second.
    static constexpr int kLookMs = 100;

    // The events since the last call, oldest first.
    std::vector<Event> take();

    void onEvent(const RunEvent& event) override;

private:
    std::function<void()> wake_;
    std::mutex mutex_;
    std::vector<Event> events_;
    bool woken_ = false;   // the scheduler was woken for what events_ holds
    bool inTest_ = false;  // between a StartTest and its EndTest
};

}  // namespace runner
}  // namespace robottestingframework
