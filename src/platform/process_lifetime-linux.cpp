// Linux: the kernel does it. PR_SET_PDEATHSIG signals a child when the thread that forked it
// ends, PR_SET_CHILD_SUBREAPER adopts orphaned descendants, a pidfd tells when a child ended.
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "platform/process.h"
#include "platform/process_lifetime.h"

namespace robottestingframework {
namespace platform {

bool armParentDeathSignalInChild(int signal, pid_t parent) {
    ::prctl(PR_SET_PDEATHSIG, signal);
    return ::getppid() == parent;  // else the parent died before the signal was armed
}

void execSearchingPath(const char* program, char* const argv[], char* const envp[]) {
    ::execvpe(program, argv, envp);
}

int openExitNotifier(pid_t pid) {
#if defined(SYS_pidfd_open)
    // glibc 2.36's <sys/pidfd.h> lacks C linkage for C++: call the kernel directly.
    return static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
#else
    (void)pid;
    return -1;
#endif
}

bool becomeSubreaper() {
    return ::prctl(PR_SET_CHILD_SUBREAPER, 1) == 0;
}

void prepareChildrenParentDeath() {}

bool setParentDeathSignal(int signal) {
    return ::prctl(PR_SET_PDEATHSIG, signal) == 0;
}

}  // namespace platform
}  // namespace robottestingframework
