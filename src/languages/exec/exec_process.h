// Runs a program to its end, collecting what it prints on stdout and stderr separately.
#pragma once

#include <sys/types.h>
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
    // Sends SIGTERM to the running program, or to the next one as soon as it starts (until
    // reset()). Thread-safe.
    void terminate();
    void reset();

private:
    std::mutex mutex_;
    pid_t pid_ = -1;
    bool terminate_ = false;
};

// "SIGSEGV", "SIGKILL", ... or "signal N".
std::string signalName(int signal);

}  // namespace languages
}  // namespace robottestingframework
