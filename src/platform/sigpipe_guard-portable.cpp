// Portable POSIX (macOS): no MSG_NOSIGNAL. A send to a gone peer raises SIGPIPE at the sending
// thread; blocked, it stays pending there and is taken with sigwait (macOS has no sigtimedwait).
#include "platform/sigpipe_guard.h"

#include <errno.h>
#include <pthread.h>

namespace robottestingframework {
namespace platform {

namespace {

sigset_t onlySigpipe() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGPIPE);
    return set;
}

bool sigpipePending() {
    sigset_t pending;
    sigemptyset(&pending);
    return ::sigpending(&pending) == 0 && sigismember(&pending, SIGPIPE) == 1;
}

}  // namespace

SigpipeGuard::SigpipeGuard() : previous_() {
    const sigset_t pipe = onlySigpipe();
    active_ = ::pthread_sigmask(SIG_BLOCK, &pipe, &previous_) == 0;
    pendingBefore_ = active_ && sigpipePending();
}

SigpipeGuard::~SigpipeGuard() {
    if (!active_) {
        return;
    }
    const int saved = errno;
    if (!pendingBefore_ && sigismember(&previous_, SIGPIPE) != 1 && sigpipePending()) {
        const sigset_t pipe = onlySigpipe();
        int taken = 0;
        ::sigwait(&pipe, &taken);
    }
    ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
    errno = saved;
}

}  // namespace platform
}  // namespace robottestingframework
