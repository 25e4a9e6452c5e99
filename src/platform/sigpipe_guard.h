// A send() or sendmsg() to a socket whose peer is gone must fail with EPIPE, not end the
// process with SIGPIPE. Linux has MSG_NOSIGNAL (noSigpipeSendFlags()); where the system has no
// such flag (macOS), a SigpipeGuard blocks SIGPIPE in the calling thread while it lives and
// takes the one a send raised meanwhile, so the runner need not ignore SIGPIPE for the whole
// process. POSIX only.
#pragma once

#include <signal.h>

namespace robottestingframework {
namespace platform {

class SigpipeGuard {
public:
    SigpipeGuard();
    // Takes a SIGPIPE raised while it lived (not one pending before), restores the signal mask;
    // errno is kept.
    ~SigpipeGuard();
    SigpipeGuard(const SigpipeGuard&) = delete;
    SigpipeGuard& operator=(const SigpipeGuard&) = delete;

private:
    bool active_ = false;
    bool pendingBefore_ = false;
    sigset_t previous_;
};

}  // namespace platform
}  // namespace robottestingframework
