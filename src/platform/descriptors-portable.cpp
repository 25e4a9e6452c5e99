// Portable POSIX (macOS): pipe and socketpair, then close-on-exec with fcntl; closing
// descriptors one by one. Between the two calls another thread's fork can inherit the new
// descriptor: the children we start close everything they were not given (spawnProcess).
#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

// macOS has no MSG_NOSIGNAL (only the SO_NOSIGPIPE socket option): writers ignore SIGPIPE.
int noSigpipeSendFlags() {
    return 0;
}

bool makePipe(FileDescriptor& readEnd, FileDescriptor& writeEnd) {
    int fds[2];
    if (::pipe(fds) != 0) {
        return false;
    }
    readEnd.reset(fds[0]);
    writeEnd.reset(fds[1]);
    setCloseOnExec(fds[0]);
    setCloseOnExec(fds[1]);
    return true;
}

bool makeSocketPair(FileDescriptor& first, FileDescriptor& second, bool packets) {
    int fds[2];
    // macOS has no local SOCK_SEQPACKET: a stream, on which fd_passing-portable.cpp frames
    // each message itself.
    (void)packets;
    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, fds) != 0) {
        return false;
    }
    first.reset(fds[0]);
    second.reset(fds[1]);
    setCloseOnExec(fds[0]);
    setCloseOnExec(fds[1]);
    return true;
}

void closeDescriptorsFrom(int first) {
    long max = ::sysconf(_SC_OPEN_MAX);
    for (long fd = first; fd < (max > 0 ? max : 1024); ++fd) {
        ::close(static_cast<int>(fd));
    }
}

}  // namespace platform
}  // namespace robottestingframework
