// Linux: one SOCK_SEQPACKET packet per message, its descriptors received close-on-exec in the
// same call (MSG_CMSG_CLOEXEC).
#include "platform/fd_passing.h"

#include <errno.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cstring>

#include "platform/scm_rights.h"

namespace robottestingframework {
namespace platform {

using fd_passing::kInFile;
using fd_passing::kInline;

// Each packet starts with its kind's byte (fd_passing.h).
bool fd_passing::sendMessage(int socket, char kind, const std::string& body,
                             const std::vector<int>& fds) {
    const std::string packet = kind + body;
    return sendWithRights(socket, packet.data(), packet.size(), fds) >= 0;
}

namespace {

// The length of the next packet, without taking it (and without taking its descriptors: no
// room for them when peeking). Lets the receive size its buffer exactly: filling 128 KiB per
// packet meant dozens of copy-on-write page faults in a fork server that just forked.
ssize_t peekLength(int socket) {
    char byte;
    iovec iov{&byte, 1};
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    ssize_t n;
    do {
        n = ::recvmsg(socket, &msg, MSG_PEEK | MSG_TRUNC);
    } while (n < 0 && errno == EINTR);
    return n;
}

}  // namespace

bool receiveWithFds(int socket, std::string& data, std::vector<FileDescriptor>& fds) {
    const ssize_t length = peekLength(socket);
    // Unknown (an error, the end) or too long: the receive below tells which, as before.
    data.resize(length > 0 && static_cast<std::size_t>(length) < kMaxPacket
                    ? static_cast<std::size_t>(length)
                    : kMaxPacket);
    fds.clear();
    int flags = 0;
    const ssize_t n =
        receiveWithRights(socket, &data[0], data.size(), MSG_CMSG_CLOEXEC, fds, flags);
    if (n <= 0) {
        data.clear();
        return false;
    }
    data.resize(static_cast<std::size_t>(n));
    if ((flags & (MSG_TRUNC | MSG_CTRUNC)) != 0 || (data[0] != kInline && data[0] != kInFile) ||
        (data[0] == kInFile && fds.empty())) {
        errno = EMSGSIZE;
        return false;
    }
    if (data[0] == kInline) {
        data.erase(0, 1);
        return true;
    }
    return fd_passing::readMessageFile(fds, data);
}

}  // namespace platform
}  // namespace robottestingframework
