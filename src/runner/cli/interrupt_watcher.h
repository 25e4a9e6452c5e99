// Turns Ctrl-C and SIGTERM into an orderly stop: the first one interrupts the run (the running
// test is stopped, tear-downs run, outputs are written); a second one ends the runner at once.
#pragma once

#include <atomic>
#include <cstdio>
#include <functional>
#include <thread>

#include "platform/signal_pipe.h"

namespace robottestingframework {
namespace runner {

class InterruptWatcher {
public:
    // `console`: where to say so (stderr is captured while tests run). `quit`: what to do
    // before quitting at once (write what is known).
    // `interrupt`: stops the run (called again and again until it ends).
    InterruptWatcher(std::function<void()> interrupt, std::FILE* console,
                     std::function<void()> quit);
    ~InterruptWatcher();
    InterruptWatcher(const InterruptWatcher&) = delete;
    InterruptWatcher& operator=(const InterruptWatcher&) = delete;

    // Stops watching and returns the first signal received, 0 when none. A signal that came
    // as the run ended counts too (or it would be lost, e.g. during --web-linger).
    int stop();
    bool interrupted() const { return received_ != 0; }

private:
    void watch(std::FILE* console);

    platform::SignalPipe signals_;
    std::function<void()> interrupt_;
    std::function<void()> quit_;
    std::atomic<bool> done_{false};
    std::atomic<int> received_{0};
    std::thread thread_;
};

}  // namespace runner
}  // namespace robottestingframework
