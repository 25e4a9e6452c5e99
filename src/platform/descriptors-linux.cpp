// Linux: pipes, socket pairs and descriptor closing in one system call each (pipe2,
// SOCK_CLOEXEC, close_range), so no other thread's fork can inherit a half-made descriptor.
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <climits>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

int noSigpipeSendFlags() {
    return MSG_NOSIGNAL;
}

bool makePipe(FileDescriptor& readEnd, FileDescriptor& writeEnd) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) {
        return false;
    }
    readEnd.reset(fds[0]);
    writeEnd.reset(fds[1]);
    return true;
}

bool makeSocketPair(FileDescriptor& first, FileDescriptor& second, bool packets) {
    int fds[2];
    int type = (packets ? SOCK_SEQPACKET : SOCK_STREAM) | SOCK_CLOEXEC;
    if (::socketpair(AF_UNIX, type, 0, fds) != 0) {
        return false;
    }
    first.reset(fds[0]);
    second.reset(fds[1]);
    return true;
}

void closeDescriptorsFrom(int first) {
#if defined(SYS_close_range)
    if (::syscall(SYS_close_range, first, UINT_MAX, 0) == 0) {
        return;
    }
#endif
    // A kernel older than 5.9.
    long max = ::sysconf(_SC_OPEN_MAX);
    for (long fd = first; fd < (max > 0 ? max : 1024); ++fd) {
        ::close(static_cast<int>(fd));
    }
}

}  // namespace platform
}  // namespace robottestingframework
