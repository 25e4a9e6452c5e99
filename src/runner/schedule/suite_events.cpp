#include "runner/schedule/suite_events.h"

namespace robottestingframework {
namespace runner {

void replay(const SuiteEvents::Event& event, TestResult& result) {
    result.publish(event);
}

std::vector<SuiteEvents::Event> SuiteEvents::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Event> taken;
    taken.swap(events_);
    return taken;
}

void SuiteEvents::onEvent(const RunEvent& event) {
    if (direct_ != nullptr) {
        replay(event, *direct_);
        return;
    }
    bool first = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        first = events_.empty();
        events_.push_back(event);
    }
    // One wake-up per batch: the scheduler takes them all at once.
    if (first && wake_) {
        wake_();
    }
}

}  // namespace runner
}  // namespace robottestingframework
