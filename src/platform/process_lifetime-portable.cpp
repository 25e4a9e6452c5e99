// Portable POSIX (macOS has no prctl, no pidfd, no execvpe): parent death is watched through a
// pipe. A process that wants its children to die with it keeps the write end of a "lifeline"
// pipe open for its whole life and never writes to it. A child that is to die with it starts a
// guard: a small process (double-forked, so no program of ours ever sees it as a child) that
// holds the read end. When the parent ends, however it ends, the kernel closes the write end,
// the guard reads end of file and signals the child. The guard leaves once the child is gone.
// No subreaper: orphaned descendants are reached through the process groups of our children.
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <mutex>

#include "platform/file_descriptor.h"
#include "platform/process.h"
#include "platform/process_lifetime.h"

extern char** environ;

namespace robottestingframework {
namespace platform {

namespace {

// The lifeline of the process `owner` (both ends close-on-exec). A child inherits its parent's
// values through fork: owner == getppid() tells it the read end there is its parent's.
struct Lifeline {
    pid_t owner = -1;
    int readEnd = -1;
    int writeEnd = -1;
};
Lifeline g_lifeline;
std::mutex g_lifelineMutex;

// How often a guard looks whether its child is still there.
constexpr int kGuardPollMs = 200;

// In the child (async-signal-safe): starts the guard of `child` on the inherited lifeline,
// then drops the child's own copies of the lifeline. False when there is no lifeline of
// `parent` to watch or the guard cannot be started.
bool startGuard(int signal, pid_t child, pid_t parent) {
    if (g_lifeline.owner != parent || g_lifeline.readEnd < 0) {
        return false;
    }
    const int watched = g_lifeline.readEnd;
    const pid_t middle = ::fork();
    if (middle == 0) {
        if (::fork() != 0) {
            ::_exit(0);  // the guard is orphaned at once: nobody of ours must reap it
        }
        // Its own session: a Ctrl-C on the terminal or a kill of the child's process group is
        // meant for the child, not for the one process that must outlive it to signal it.
        ::setsid();
        ::dup2(watched, 0);
        closeDescriptorsFrom(1);
        for (;;) {
            pollfd lifeline{0, POLLIN, 0};
            const int ready = ::poll(&lifeline, 1, kGuardPollMs);
            if (ready > 0) {
                // End of file: the parent is gone (nobody writes on a lifeline).
                ::kill(child, signal);
                ::_exit(0);
            }
            if (ready < 0 && errno != EINTR) {
                ::_exit(0);
            }
            if (::kill(child, 0) != 0) {
                ::_exit(0);  // the child ended and was reaped
            }
        }
    }
    if (middle > 0) {
        int status;
        while (::waitpid(middle, &status, 0) < 0 && errno == EINTR) {
        }
    }
    // The child must not keep its parent's lifeline alive.
    ::close(g_lifeline.readEnd);
    ::close(g_lifeline.writeEnd);
    g_lifeline = Lifeline{};
    return middle > 0;
}

}  // namespace

void prepareChildrenParentDeath() {
    std::lock_guard<std::mutex> lock(g_lifelineMutex);
    const pid_t self = ::getpid();
    if (g_lifeline.owner == self) {
        return;
    }
    // One inherited from our parent (a fork of ours that did not exec) is not ours to keep.
    if (g_lifeline.owner >= 0) {
        ::close(g_lifeline.readEnd);
        ::close(g_lifeline.writeEnd);
        g_lifeline = Lifeline{};
    }
    FileDescriptor readEnd, writeEnd;
    if (makePipe(readEnd, writeEnd)) {
        g_lifeline = Lifeline{self, readEnd.release(), writeEnd.release()};
    }
}

bool armParentDeathSignalInChild(int signal, pid_t parent) {
    return startGuard(signal, ::getpid(), parent) && ::getppid() == parent;
}

void execSearchingPath(const char* program, char* const argv[], char* const envp[]) {
    // In the child between fork and exec: replacing the environment changes nobody else's.
    environ = const_cast<char**>(envp);
    ::execvp(program, argv);
}

int openExitNotifier(pid_t) {
    return -1;
}

bool becomeSubreaper() {
    return false;
}

bool setParentDeathSignal(int signal) {
    return startGuard(signal, ::getpid(), ::getppid());
}

}  // namespace platform
}  // namespace robottestingframework
