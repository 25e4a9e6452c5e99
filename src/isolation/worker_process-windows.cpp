// Windows: the runner starts each worker itself (no fork): robottestingframework-worker.exe
// --worker IN OUT, with IN the pipe its request (and a fixture's calls) come on, OUT the pipe
// its events go out on, both as inherited handles, and its stdout and stderr one more pipe.
// The worker runs in a job object that kills on close, so the test's children end with it.
// Windows cannot wait on a pipe and a process at once: the wait is bounded polling.
#include <windows.h>

#include <algorithm>

#include "isolation/request_pipe.h"
#include "isolation/worker_process.h"
#include "platform/clock.h"
#include "platform/job_process.h"

namespace robottestingframework {
namespace isolation {

namespace {

// How often a wait looks at the process besides the pipes.
constexpr int kPollMs = 20;

}  // namespace

WorkerProcess::~WorkerProcess() {
    // Closing the job ends whatever is left: the worker, or the children the test left.
    job_.reset();
}

bool WorkerProcess::start(ForkServer& server, const WorkRequest& request, std::string& error,
                          bool /*waitForPid*/, const std::vector<int>& /*network*/) {
    platform::FileDescriptor callsRead, eventsWrite, outputWrite;
    if (!platform::makePipe(callsRead, calls_) || !platform::makePipe(channel_, eventsWrite) ||
        !platform::makePipe(output_fd_, outputWrite)) {
        error = "cannot create the worker's pipes";
        exited_ = true;
        return false;
    }
    platform::JobProcessOptions options;
    options.argv = {server.workerPath(), "--worker", platform::handleValue(callsRead.get()),
                    platform::handleValue(eventsWrite.get())};
    options.stdoutFd = outputWrite.get();
    options.stderrFd = outputWrite.get();
    options.inheritedFds = {callsRead.get(), eventsWrite.get()};
    job_ = std::make_shared<platform::JobProcess>();
    if (!job_->start(options, error)) {
        exited_ = true;
        return false;
    }
    pid_ = static_cast<pid_t>(job_->pid());
    // Only the worker holds the writing ends now, so end of file means what it should.
    callsRead.reset();
    eventsWrite.reset();
    outputWrite.reset();
    platform::setNonBlocking(channel_.get());
    platform::setNonBlocking(output_fd_.get());
    if (!platform::writeAll(calls_.get(), frameRequest(request))) {
        error = "the worker did not take its request";
        return false;
    }
    if (request.role == WorkRequest::Role::Test) {
        calls_.reset();  // a test takes no calls
    }
    return true;
}

bool WorkerProcess::learnPid(double) {
    return pid_ > 0;  // known from the start
}

void WorkerProcess::readStatus(std::vector<WireRecord>& records) {
    // The worker ended: everything it wrote is in the pipes (a child it left may still hold
    // the output pipe open, so read what is there, not to its end).
    if (channel_.valid()) {
        readChannel(records, true);
    }
    if (output_fd_.valid()) {
        readOutput(true);
    }
    status_ = static_cast<int>(job_->exitCode());
    exited_ = true;
}

bool WorkerProcess::collect(int timeoutMs, std::vector<WireRecord>& records, int wake,
                            bool* woken) {
    if (exited_) {
        return true;
    }
    platform::Deadline deadline(timeoutMs < 0 ? 0 : timeoutMs / 1000.0);
    for (;;) {
        if (job_ && job_->ended()) {
            readStatus(records);
            return true;
        }
        const int slice = timeoutMs < 0 ? kPollMs : std::min(kPollMs, deadline.remainingMs());
        std::vector<bool> ready;
        if (platform::waitReadable({channel_.get(), output_fd_.get(), wake}, slice, ready)) {
            if (ready[0]) {
                readChannel(records, false);
            }
            if (ready[1]) {
                readOutput(false);
            }
            if (woken != nullptr) {
                *woken = ready[2];
            }
            return true;
        }
        if (timeoutMs == 0 || (timeoutMs > 0 && deadline.expired())) {
            return false;
        }
    }
}

bool WorkerProcess::send(const WireRecord& record) {
    return calls_.valid() && !exited_ && platform::writeAll(calls_.get(), encode(record));
}

void WorkerProcess::signal(int) {
    // Windows has no signal to ask with: whatever is asked, the job ends.
    if (job_ && !exited_) {
        job_->kill();
    }
}

bool WorkerProcess::stop(double, std::vector<WireRecord>& records) {
    signal(0);
    pumpUntilEnd(kKilledSeconds, records);
    // Nothing polite was tried, so nothing was ignored: not "it ignored SIGTERM".
    return true;
}

}  // namespace isolation
}  // namespace robottestingframework
