// The runner's view of one worker: the pipes to and from it, its pid and how it ended. Used
// the same way for tests and fixtures.
#pragma once

#include <sys/types.h>

#include <memory>
#include <string>
#include <vector>

#include "isolation/fork_server_client.h"
#include "isolation/wire_format.h"
#include "languages/output_tail.h"
#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {
class JobProcess;  // Windows (platform/job_process.h)
}  // namespace platform
namespace isolation {

// The last bytes a worker printed (64 KiB), bounded so a chatty test cannot fill the runner's
// memory.
using languages::OutputTail;

class WorkerProcess {
public:
    WorkerProcess() = default;
    ~WorkerProcess();
    WorkerProcess(const WorkerProcess&) = delete;
    WorkerProcess& operator=(const WorkerProcess&) = delete;

    // Asks `server` for a worker. With `waitForPid`, waits (bounded) until the server reports
    // the worker's pid; without, the pid arrives with the worker's first events (a test need
    // not wait a round trip for it) and is waited for only when the worker must be signalled.
    // `network`: the namespaces of a private network the worker joins before anything else
    // (platform/private_network.h); empty: the machine's network.
    bool start(ForkServer& server, const WorkRequest& request, std::string& error,
               bool waitForPid = true, const std::vector<int>& network = {});
    // -1 until the server reported it.
    pid_t pid() const { return pid_; }

    // Waits up to `timeoutMs` (-1: forever) for the worker to send or print something, or to
    // end; records received are appended to `records`. `wake` (if >= 0) also ends the wait
    // (an interrupt); its readiness is returned in `woken`. False on timeout.
    bool pump(int timeoutMs, std::vector<WireRecord>& records, int wake = -1,
              bool* woken = nullptr);
    // True once the fork server reported the worker ended; waitStatus() tells how.
    bool exited() const { return exited_; }
    int waitStatus() const { return status_; }
    // The channel carried garbage: the worker cannot be trusted to report any more.
    bool corrupt() const { return corrupt_; }

    // Sends a record to the worker (fixture calls). False when it is gone.
    bool send(const WireRecord& record);
    // Signals the worker's whole process group (until it is known to have ended).
    void signal(int signal);
    // SIGTERM to the group, up to `grace` seconds (pumping records into `records`), then
    // SIGKILL; returns once the worker ended (bounded: 10 s after the SIGKILL).
    // Returns true when SIGTERM was enough.
    bool stop(double grace, std::vector<WireRecord>& records);

    OutputTail& output() { return output_; }
    // Reads whatever output is already waiting in the pipe (the worker said it is done).
    void drainOutput();
    // Our end of the channel (fixture calls go out on a duplicate of it).
    int channel() const { return channel_.get(); }

private:
    // Reads until the server reported the pid (or the worker ended); false after `seconds`.
    bool learnPid(double seconds);
    // pump() without the backlog; sets `woken` only when `wake` became readable (pump() clears
    // it first).
    bool collect(int timeoutMs, std::vector<WireRecord>& records, int wake, bool* woken);
    // Read in 64 KiB: less means the pipe was emptied, and the next poll says when more comes.
    static constexpr long kReadSize = 65536;
    // `all`: until nothing is left (the worker ended); else one read unless it filled the
    // buffer (the next poll tells when more came).
    void readChannel(std::vector<WireRecord>& records, bool all);
    void readOutput(bool all);
    void readStatus(std::vector<WireRecord>& records);
    // Pumps (into `records`) until the worker ended or `seconds` passed; true when it ended.
    bool pumpUntilEnd(double seconds, std::vector<WireRecord>& records);
    // How long a killed worker is waited for.
    static constexpr double kKilledSeconds = 10.0;

    platform::FileDescriptor channel_, output_fd_, status_fd_;
    WireDecoder events_, statuses_;
    std::vector<WireRecord> backlog_;  // received while waiting for the pid
    OutputTail output_;
    // Windows: the worker in its job object, started by us (no fork server), and the pipe its
    // request and fixture calls go out on. Unused on POSIX.
    std::shared_ptr<platform::JobProcess> job_;
    platform::FileDescriptor calls_;
    pid_t pid_ = -1;
    bool exited_ = false;
    bool corrupt_ = false;
    int status_ = 0;
};

}  // namespace isolation
}  // namespace robottestingframework
