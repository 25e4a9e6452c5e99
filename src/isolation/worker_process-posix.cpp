// POSIX: the fork server starts each worker in a process group of its own and reports its pid
// and exit status on the status pipe; stopping it signals the group.
#include "isolation/worker_process.h"

#include <errno.h>
#include <signal.h>

#include "platform/clock.h"
#include "platform/coverage.h"
#include "platform/process_tree.h"

namespace robottestingframework {
namespace isolation {

WorkerProcess::~WorkerProcess() {
    if (pid_ > 0 && !exited_ && platform::coverageBuild()) {
        // A worker that finished writes its coverage counters before it exits: let it (10 s at
        // most) instead of killing it halfway.
        platform::Deadline deadline(10.0);
        std::vector<WireRecord> ignored;
        while (!exited_ && !deadline.expired()) {
            collect(deadline.remainingMs(), ignored, -1, nullptr);
            ignored.clear();
        }
    }
    if (pid_ > 0 && !exited_) {
        // Whatever is left of the worker's group goes now (it may be a worker that finished and
        // is exiting, or the children it left). The fork server reaps; nobody waits here.
        platform::signalProcessGroup(pid_, SIGKILL);
    }
}

bool WorkerProcess::start(ForkServer& server, const WorkRequest& request, std::string& error,
                          bool waitForPid, const std::vector<int>& network) {
    platform::FileDescriptor theirChannel, outputWrite, statusWrite;
    if (!platform::makeSocketPair(channel_, theirChannel, false) ||
        !platform::makePipe(output_fd_, outputWrite) ||
        !platform::makePipe(status_fd_, statusWrite)) {
        error = "cannot create the worker's pipes";
        return false;
    }
    pid_t pid = -1;
    if (!server.spawn(request, theirChannel.get(), outputWrite.get(), statusWrite.get(), error,
                      &pid, network)) {
        return false;
    }
    if (pid > 0) {
        pid_ = pid;  // a spare the server handed over: known now, not with Started
    }
    // Only the worker (and the server, for the status) may hold the writing ends now, so end
    // of file means what it should.
    theirChannel.reset();
    outputWrite.reset();
    statusWrite.reset();
    platform::setNewNonBlocking(channel_.get());
    platform::setNewNonBlocking(output_fd_.get());
    platform::setNewNonBlocking(status_fd_.get());

    if (!waitForPid || learnPid(10.0)) {
        return true;
    }
    error = exited_ ? "the fork server could not start a worker" : "the fork server did not answer";
    exited_ = true;
    return false;
}

bool WorkerProcess::learnPid(double seconds) {
    platform::Deadline deadline(seconds);
    // The worker may write (even end) before the server tells us its pid: keep what comes.
    std::vector<WireRecord> early;
    while (pid_ <= 0 && !exited_ && !deadline.expired()) {
        early.clear();
        collect(deadline.remainingMs(), early, -1, nullptr);
        backlog_.insert(backlog_.end(), early.begin(), early.end());
    }
    return pid_ > 0;
}

void WorkerProcess::readStatus(std::vector<WireRecord>& records) {
    std::string bytes;
    long n;
    while ((n = platform::readSome(status_fd_.get(), bytes, kReadSize)) > 0) {
        statuses_.feed(bytes);
        bytes.clear();
        if (n < kReadSize) {
            break;  // the end of file, if it came, is seen on the next poll
        }
    }
    bool gone = n == 0;
    bool reported = false;
    WireRecord record;
    while (statuses_.next(record) == WireDecoder::Status::Record) {
        if (record.kind == WireKind::Started) {
            pid_ = static_cast<pid_t>(record.number);
        } else if (record.kind == WireKind::Exited) {
            status_ = static_cast<int>(record.number);
            gone = true;
            reported = true;
        }
    }
    if (gone) {
        // Everything the worker wrote before it ended is in the pipes now: take it all.
        if (channel_.valid()) {
            readChannel(records, true);
        }
        if (output_fd_.valid()) {
            readOutput(true);
        }
        status_fd_.reset();
        exited_ = true;
        if (!reported && pid_ > 0) {
            // The server vanished without telling: count it as killed.
            status_ = SIGKILL;
        }
    }
}

bool WorkerProcess::collect(int timeoutMs, std::vector<WireRecord>& records, int wake,
                            bool* woken) {
    if (exited_) {
        return true;
    }
    std::vector<bool> ready;
    if (!platform::waitReadable({channel_.get(), output_fd_.get(), status_fd_.get(), wake},
                                timeoutMs, ready)) {
        return false;
    }
    if (ready[0]) {
        readChannel(records, false);
    }
    if (ready[1]) {
        readOutput(false);
    }
    if (ready[2]) {
        readStatus(records);
    }
    if (woken != nullptr) {
        *woken = ready[3];
    }
    return true;
}

bool WorkerProcess::send(const WireRecord& record) {
    return channel_.valid() && !exited_ && platform::sendAll(channel_.get(), encode(record));
}

void WorkerProcess::signal(int signal) {
    if (pid_ <= 0 && !exited_) {
        learnPid(10.0);
    }
    if (pid_ > 0 && !exited_) {
        platform::signalProcessGroup(pid_, signal);
    }
}

bool WorkerProcess::stop(double grace, std::vector<WireRecord>& records) {
    signal(SIGTERM);
    signal(SIGCONT);  // a stopped worker acts on SIGTERM only once continued
    if (pumpUntilEnd(grace > 0 ? grace : 1e-6, records)) {
        return true;
    }
    signal(SIGKILL);
    pumpUntilEnd(kKilledSeconds, records);
    return false;
}

}  // namespace isolation
}  // namespace robottestingframework
