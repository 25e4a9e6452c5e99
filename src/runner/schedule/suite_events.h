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

    // `wake`: called (on the reporting thread) to wake the scheduler: once per batch of events;
    // while a test runs, not before it ends; for a test's end, not again within kLookMs of the
    // last wake-up (see kLookMs).
    explicit SuiteEvents(std::function<void()> wake) : wake_(std::move(wake)) {}

    // How long the scheduler may leave events kept: those of a running test (its start, its
    // checks), and the end of a test that came within kLookMs of the last wake-up. It looks
    // this often while suites run. Waking it for each one cost two thread switches and five
    // system calls a test, for a line no one can read at a thousand tests a second. Any
    // other event outside a test (a suite's end, its fixture's) wakes it at once.
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
    double lastWake_ = 0;  // steady seconds of the last wake-up
};

}  // namespace runner
}  // namespace robottestingframework
