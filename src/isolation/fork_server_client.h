// The runner's handle on its fork server (see fork_server_loop.h): started once per run,
// asked to start one worker per test or fixture. Stopping it (or the runner dying) ends every
// process the run started.
#pragma once

#include <sys/types.h>

#include <mutex>
#include <string>
#include <vector>

#include "isolation/wire_format.h"
#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace isolation {

class ForkServer {
public:
    ForkServer() = default;
    ~ForkServer();
    ForkServer(const ForkServer&) = delete;
    ForkServer& operator=(const ForkServer&) = delete;

    // Starts `workerPath --fork-server 3`. Call it from a thread that lives as long as the run:
    // the server takes its parent-death signal from that thread (Linux). With `verbose`, the
    // server says on stderr which script languages it pre-started (fork_server_loop.h).
    bool start(const std::string& workerPath, std::string& error, bool verbose = false);
    bool running() const { return pid_ > 0; }
    pid_t pid() const { return pid_; }

    // Asks for a worker running `request`. `channel` becomes its fd 3 (events out, calls in),
    // `output` its stdout and stderr; Started and Exited records are written to `status`.
    // A test or fixture that is not a script goes straight to a spare the server handed over
    // (fork_server_loop.h); its pid is then known at once, set in `pid` when given. Scripts
    // go through the server, which hands them to its pre-started interpreter. `network`: the
    // namespaces of a private network, passed along for the worker to join. Thread-safe.
    bool spawn(const WorkRequest& request, int channel, int output, int status, std::string& error,
               pid_t* pid = nullptr, const std::vector<int>& network = {});

    // Ends the server and, through it, every worker and their descendants. Waits (bounded).
    void stop();

    // Windows has no fork: there the runner starts each worker itself from this program
    // (WorkerProcess), and "the server" is only where the worker is; start() checks it exists.
    const std::string& workerPath() const { return workerPath_; }

private:
    struct Spare {
        pid_t pid = -1;
        platform::FileDescriptor link;  // the spare reads its request from the other end
    };
    // The next spare the server handed over, waiting (bounded) for its note if none is here
    // yet. False when none comes (the server is gone, or cannot fork).
    bool takeSpare(Spare& spare);

    platform::FileDescriptor control_;
    std::string workerPath_;
    pid_t pid_ = -1;
    std::mutex mutex_;
    std::vector<Spare> spares_;  // handed over, not used yet (oldest first)
};

// Set beside LD_BIND_NOW when the runner set it for the server (not the user): the server
// takes both out of its environment, which the tests inherit.
constexpr const char* kBindNowMark = "RTF_WORKER_BIND_NOW";

// Where robottestingframework-worker is: $RTF_WORKER when set, next to the running program,
// in ../libexec beside it, then where it was installed. Empty when not found.
std::string findWorker();

}  // namespace isolation
}  // namespace robottestingframework
