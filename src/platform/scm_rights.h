// One sendmsg/recvmsg carrying descriptors (SCM_RIGHTS): the part of passing descriptors that is
// the same whether the socket keeps message boundaries (Linux) or is a stream (portable POSIX).
// Both fd_passing files frame their messages on top of it.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <vector>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

// Sends `size` bytes at `data` with duplicates of `fds` (at most kMaxPassedFds + 1) in one
// sendmsg, retried on EINTR, without SIGPIPE. What sendmsg returned: bytes sent, or -1.
ssize_t sendWithRights(int socket, const char* data, std::size_t size, const std::vector<int>& fds);

// One recvmsg of at most `size` bytes into `buffer` with `flags`, retried on EINTR. The
// descriptors that came with it are appended to `fds`; `messageFlags` gets msg_flags
// (MSG_TRUNC, MSG_CTRUNC). What recvmsg returned: bytes received, 0 at the end, or -1.
ssize_t receiveWithRights(int socket, char* buffer, std::size_t size, int flags,
                          std::vector<FileDescriptor>& fds, int& messageFlags);

}  // namespace platform
}  // namespace robottestingframework
