// Runs a program to its end, collecting what it prints on stdout and stderr separately.
#pragma once

#include <sys/types.h>
#include <chrono>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace robottestingframework {
namespace languages {

struct ExecOutcome {
    bool started = false;
    std::string startError;  // why it could not be started
    int exitStatus = -1;     // when it exited
    int signal = 0;          // when a signal ended it
    std::string out;
    std::string err;
};

class ExecProcess {
public:
    // Runs argv[0] (a path) with argv, the environment of this process plus `environment`
    // (name, value pairs), stdin from /dev/null. Returns once it has ended.
    ExecOutcome run(const std::vector<std::string>& argv,
                    const std::vector<std::pair<std::string, std::string>>& environment);
    // Stops the running program and everything in its process group (SIGTERM, then SIGKILL
    // after a grace), or the next one as soon as it starts (until reset()). Thread-safe.
    // Whatever the program left in its group is stopped when it ends, in any case.
    void terminate();
    void reset();

private:
    std::mutex mutex_;
    pid_t pid_ = -1;
    bool terminate_ = false;
    std::chrono::steady_clock::time_point terminatedAt_;
};

// "SIGSEGV", "SIGKILL", ... or "signal N".
std::string signalName(int signal);

}  // namespace languages
}  // namespace robottestingframework
