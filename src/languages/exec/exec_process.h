// Runs a program to its end, handing what it prints on stdout and stderr to the caller as it
// arrives (nothing is accumulated here: a program may print without end).
#pragma once

#include <sys/types.h>
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace robottestingframework {
namespace platform {
class JobProcess;  // Windows (platform/job_process.h)
}  // namespace platform
namespace languages {

struct ExecOutcome {
    bool started = false;
    std::string startError;  // why it could not be started
    int exitStatus = -1;     // when it exited
    int signal = 0;          // when a signal ended it
};

// What the guard given to setExecGuard (test_loader.h) returns now; empty without one.
std::string execGuardEntry();

class ExecProcess {
public:
    using Sink = std::function<void(const char* data, std::size_t size)>;

    // Runs argv[0] (a path) with argv, the environment of this process plus `environment`
    // (name, value pairs), stdin from /dev/null, in a process group of its own that gets
    // SIGKILL if this thread dies. `out` and `err` get its output as it comes. When a stop is
    // asked for (terminate()), `stopping` is called once, before the program is stopped, so
    // that the caller can report what it has while it still may. Returns once it has ended.
    ExecOutcome run(const std::vector<std::string>& argv,
                    const std::vector<std::pair<std::string, std::string>>& environment,
                    const Sink& out, const Sink& err, const std::function<void()>& stopping);
    // Stops the running program and everything in its process group (SIGTERM, then SIGKILL
    // after a grace), or the next one as soon as it starts (until reset()). Thread-safe.
    // Whatever the program left in its group is stopped when it ends, in any case.
    void terminate();
    void reset();

private:
    // Per platform (exec_process-<platform>.cpp). Starts the program with its stdout and
    // stderr on `outFd` and `errFd`; false with `error` when it cannot.
    bool start(const std::vector<std::string>& argv,
               const std::vector<std::pair<std::string, std::string>>& environment, int outFd,
               int errFd, std::string& error);
    // Reads the pipes into the sinks until the program has ended (calling tellStopping on the
    // way), then fills in how it ended.
    void waitForEnd(int outFd, int errFd, const Sink& out, const Sink& err,
                    const std::function<void()>& stopping, ExecOutcome& outcome);
    // Stops the running program, if any; called with mutex_ held.
    void stopRunning();
    // Calls `stopping` once (`told` remembers) when terminate() has been asked for.
    void tellStopping(bool& told, const std::function<void()>& stopping);

    std::mutex mutex_;
    pid_t pid_ = -1;
    std::shared_ptr<platform::JobProcess> job_;  // Windows: the running program's job
    bool terminate_ = false;
    std::chrono::steady_clock::time_point terminatedAt_;
};

}  // namespace languages
}  // namespace robottestingframework
