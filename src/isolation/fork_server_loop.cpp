#include "fork_server_loop.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <map>
#include <thread>

#include "clock.h"
#include "fd_passing.h"
#include "file_descriptor.h"
#include "process.h"
#include "process_tree.h"
#include "signal_pipe.h"
#include "wire_format.h"
#include "worker.h"

namespace robottestingframework {
namespace isolation {

namespace {

using platform::FileDescriptor;

// In a freshly forked child: the state every worker starts from. Returns in the child.
void prepareChild(pid_t server) {
    platform::SignalPipe::resetInChild();
    ::signal(SIGPIPE, SIG_DFL);
    ::setpgid(0, 0);
    platform::setParentDeathSignal(SIGKILL);
    if (::getppid() != server) {
        ::_exit(125);
    }
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
}

// Become the worker of `request`. Never returns.
[[noreturn]] void becomeWorker(const WorkRequest& request, int channel, int output) {
    // 0: /dev/null, 1 and 2: the output pipe, 3: the channel; nothing else is inherited.
    int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    int high = ::fcntl(channel, F_DUPFD_CLOEXEC, 10);
    int out = ::fcntl(output, F_DUPFD_CLOEXEC, 10);
    ::dup2(null, 0);
    ::dup2(out, 1);
    ::dup2(out, 2);
    ::dup3(high, 3, O_CLOEXEC);  // a program the test runs must not write on our channel
    platform::closeDescriptorsFrom(4);
    // Line-buffered, so what a test printed just before it crashed still reaches the report.
    ::setvbuf(stdout, nullptr, _IOLBF, 0);

    int code = request.role == WorkRequest::Role::Fixture ? runFixtureWorker(request, 3)
                                                          : runTestWorker(request, 3);
    ::fflush(stdout);
    ::fflush(stderr);
    ::_exit(code);
}

// A spare: forked ahead of time, so the fork is not on the path of the next test. It waits
// on `link` for its request and the two descriptors, then becomes that worker.
[[noreturn]] void waitAsSpare(int link, pid_t server) {
    prepareChild(server);
    ::dup2(link, 4);
    platform::closeDescriptorsFrom(5);
    ::close(3);
    std::string packet;
    std::vector<FileDescriptor> fds;
    WorkRequest request;
    if (!platform::receiveWithFds(4, packet, fds) || fds.size() != 2 ||
        !decodeRequest(packet, request)) {
        ::_exit(0);  // the server is gone or shutting down
    }
    becomeWorker(request, fds[0].get(), fds[1].get());
}

struct Spare {
    pid_t pid = -1;
    FileDescriptor link;
};

// Forks the next spare; false (no spare) when fork fails.
bool makeSpare(Spare& spare, pid_t server) {
    FileDescriptor ours, theirs;
    if (!platform::makeSocketPair(ours, theirs, true)) {
        return false;
    }
    pid_t pid = ::fork();
    if (pid == 0) {
        waitAsSpare(theirs.get(), server);
    }
    if (pid < 0) {
        return false;
    }
    // Both sides set the group, so it exists before anyone signals it.
    ::setpgid(pid, pid);
    spare.pid = pid;
    spare.link = std::move(ours);
    return true;
}

bool sendStatus(int fd, WireKind kind, std::int64_t number) {
    WireRecord record;
    record.kind = kind;
    record.number = number;
    return platform::writeAll(fd, encode(record));
}

// Kills every descendant until none is left, reaping as they go. Bounded.
void killEverything() {
    pid_t self = ::getpid();
    platform::Deadline deadline(5.0);
    while (!deadline.expired()) {
        std::size_t killed = platform::killDescendants(self);
        int status;
        while (::waitpid(-1, &status, WNOHANG) > 0) {
        }
        if (killed == 0 && platform::descendantsOf(self).empty()) {
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    int status;
    while (::waitpid(-1, &status, WNOHANG) > 0) {
    }
}

}  // namespace

int serveForkRequests(int control) {
    ::signal(SIGPIPE, SIG_IGN);  // a runner that went away must not kill us before we clean up
    platform::SignalPipe signals({SIGCHLD, SIGTERM, SIGINT, SIGHUP});
    platform::becomeSubreaper();
    // Also covered by the control socket's end of file; this catches a runner whose socket
    // leaked into another process.
    platform::setParentDeathSignal(SIGTERM);

    pid_t self = ::getpid();
    std::map<pid_t, FileDescriptor> statusOf;  // live workers -> where their status goes
    bool running = true;
    std::string packet;
    std::vector<FileDescriptor> fds;
    std::vector<bool> ready;
    Spare spare;
    while (running) {
        // The next worker is forked while the runner is busy with the current one.
        if (spare.pid < 0) {
            makeSpare(spare, self);
        }
        platform::waitReadable({control, signals.fd()}, -1, ready);
        if (ready[1]) {
            while (int signal = signals.take()) {
                if (signal != SIGCHLD) {
                    running = false;
                }
            }
            int status;
            pid_t pid;
            while ((pid = ::waitpid(-1, &status, WNOHANG)) > 0) {
                auto it = statusOf.find(pid);
                if (it != statusOf.end()) {
                    // What the worker left behind in its group goes with it.
                    platform::signalProcessGroup(pid, SIGKILL);
                    sendStatus(it->second.get(), WireKind::Exited, status);
                    statusOf.erase(it);
                }
                if (pid == spare.pid) {
                    spare.pid = -1;  // the spare died waiting (killed from outside)
                    spare.link.reset();
                }
                // Otherwise an orphan that was re-parented to us: reaped, nothing to say.
            }
        }
        if (ready[0] && running) {
            if (!platform::receiveWithFds(control, packet, fds)) {
                if (errno == EMSGSIZE) {
                    continue;
                }
                break;  // the runner is gone
            }
            WorkRequest request;
            if (fds.size() != 3 || !decodeRequest(packet, request)) {
                continue;  // not a request we understand; its descriptors close here
            }
            // Hand the request to the spare (forking one now if there is none).
            pid_t pid = -1;
            for (int attempt = 0; attempt < 2 && pid < 0; ++attempt) {
                if (spare.pid < 0 && !makeSpare(spare, self)) {
                    break;
                }
                if (platform::sendWithFds(spare.link.get(), packet, {fds[0].get(), fds[1].get()})) {
                    pid = spare.pid;
                } else {
                    ::kill(spare.pid, SIGKILL);  // a broken spare; reaped as an orphan
                }
                spare.link.reset();
                spare.pid = -1;
            }
            if (pid < 0) {
                sendStatus(fds[2].get(), WireKind::Exited, -1);
                fds.clear();
                continue;
            }
            sendStatus(fds[2].get(), WireKind::Started, pid);
            statusOf[pid] = std::move(fds[2]);
            fds.clear();
        }
    }
    spare.link.reset();
    killEverything();
    return 0;
}

}  // namespace isolation
}  // namespace robottestingframework
