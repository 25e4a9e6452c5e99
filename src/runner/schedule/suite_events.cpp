#include "runner/schedule/suite_events.h"

#include "platform/clock.h"

namespace robottestingframework {

namespace runner {

namespace {}  // namespace

std::vector<SuiteEvents::Event> SuiteEvents::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Event> taken;
    taken.swap(events_);
    woken_ = false;
    return taken;
}

void SuiteEvents::onEvent(const RunEvent& event) {
    bool wake = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        events_.push_back(event);
        // A kept event carries when it happened: the collector times it so when it is published
        // later, and the reports' start times, durations and timeline lanes are the suite's own.
        const double now = platform::monotonicSeconds();
        events_.back().happened = now;
        const ResultEvent::Kind kind = event.data.kind;
        const bool testEnded = endsTest(kind);
        if (startsTest(kind)) {
            inTest_ = true;
        } else if (testEnded) {
            inTest_ = false;
        }
        // One wake-up per batch: the scheduler takes them all at once. A running test's
        // events wait for its end, or for the scheduler's next look (kLookMs); so does the end
        // of a test that came soon after the last wake-up.
        wake = !woken_ && !inTest_ && (!testEnded || now - lastWake_ >= kLookMs / 1000.0);
        woken_ = woken_ || wake;
        if (wake) {
            lastWake_ = now;
        }
    }
    if (wake && wake_) {
        wake_();
    }
}

}  // namespace runner
}  // namespace robottestingframework
