#include "runner/cli/interrupt_watcher.h"

#include <signal.h>
#include <unistd.h>

#include "platform/coverage.h"
#include "platform/process_tree.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/program_name.h"

namespace robottestingframework {
namespace runner {

InterruptWatcher::InterruptWatcher(std::function<void()> interrupt, std::FILE* console,
                                   std::function<void()> quit)
    : signals_({SIGINT, SIGTERM}),
      interrupt_(std::move(interrupt)),
      quit_(std::move(quit)),
      thread_([this, console] { watch(console); }) {}

InterruptWatcher::~InterruptWatcher() {
    stop();
}

int InterruptWatcher::stop() {
    if (thread_.joinable()) {
        done_ = true;
        signals_.wake();  // or the run would end up to one poll period (200 ms) late
        thread_.join();
        // The pipe may hold the wake-up byte (0) before the signal.
        for (int i = 0; i < 3 && received_ == 0; ++i) {
            received_ = signals_.take();
        }
    }
    return received_;
}

void InterruptWatcher::watch(std::FILE* console) {
    while (!done_) {
        int signal = signals_.wait(200);
        if (signal != 0 && received_ == 0) {
            received_ = signal;
            std::fprintf(console,
                         "\n%s: interrupted; stopping the running test and tearing down "
                         "(again to quit at once)\n",
                         programName);
            std::fflush(console);
        } else if (signal != 0) {
            std::fprintf(console, "%s: interrupted again; writing what is known and quitting\n",
                         programName);
            std::fflush(console);
            // The outputs first, with the run as it stands: the collector leaves the run
            // before anything is killed, so a fixture or test killed now is not recorded as
            // having died (a hung tearDown read "died in tearDown: killed by SIGKILL" instead of
            // "the runner quit" when its worker's end came first). Then whatever the run
            // started goes with us: the fork server kills its workers when we are gone; what
            // the runner itself started (in-process tests) is killed here.
            quit_();
            platform::killDescendants(::getpid());
            platform::flushCoverage();
            ::_exit(interruptedBy(received_));
        }
        if (received_ != 0) {
            // Again and again: an interruption that arrives while a test is being started
            // could be missed by it; the runner starts no new test once interrupted.
            interrupt_();
        }
    }
}

}  // namespace runner
}  // namespace robottestingframework
