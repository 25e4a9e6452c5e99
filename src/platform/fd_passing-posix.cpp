#include "fd_passing.h"

#include <errno.h>
#include <sys/socket.h>
#include <sys/uio.h>

#include <cstring>

namespace robottestingframework {
namespace platform {

bool sendWithFds(int socket, const std::string& data, const std::vector<int>& fds) {
    if (data.size() > kMaxPacket || fds.size() > kMaxPassedFds) {
        errno = EMSGSIZE;
        return false;
    }
    // A zero-length packet cannot carry descriptors reliably; there is always one byte.
    char dummy = 0;
    iovec iov{};
    iov.iov_base = data.empty() ? &dummy : const_cast<char*>(data.data());
    iov.iov_len = data.empty() ? 1 : data.size();

    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int) * kMaxPassedFds)];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    if (!fds.empty()) {
        std::memset(control, 0, sizeof(control));
        msg.msg_control = control;
        msg.msg_controllen = CMSG_SPACE(sizeof(int) * fds.size());
        cmsghdr* header = CMSG_FIRSTHDR(&msg);
        header->cmsg_level = SOL_SOCKET;
        header->cmsg_type = SCM_RIGHTS;
        header->cmsg_len = CMSG_LEN(sizeof(int) * fds.size());
        std::memcpy(CMSG_DATA(header), fds.data(), sizeof(int) * fds.size());
    }
    for (;;) {
        ssize_t n = ::sendmsg(socket, &msg, MSG_NOSIGNAL);
        if (n >= 0) {
            return true;
        }
        if (errno != EINTR) {
            return false;
        }
    }
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
    iovec iov{};
    iov.iov_base = &data[0];
    iov.iov_len = data.size();
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int) * kMaxPassedFds)];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof(control);
    ssize_t n;
    do {
        n = ::recvmsg(socket, &msg, MSG_CMSG_CLOEXEC);
    } while (n < 0 && errno == EINTR);
    fds.clear();
    if (n > 0) {
        for (cmsghdr* header = CMSG_FIRSTHDR(&msg); header != nullptr;
             header = CMSG_NXTHDR(&msg, header)) {
            if (header->cmsg_level == SOL_SOCKET && header->cmsg_type == SCM_RIGHTS) {
                std::size_t count = (header->cmsg_len - CMSG_LEN(0)) / sizeof(int);
                for (std::size_t i = 0; i < count; ++i) {
                    int fd;
                    std::memcpy(&fd, CMSG_DATA(header) + i * sizeof(int), sizeof(int));
                    fds.emplace_back(fd);
                }
            }
        }
    }
    if (n <= 0) {
        data.clear();
        return false;
    }
    data.resize(static_cast<std::size_t>(n));
    if ((msg.msg_flags & (MSG_TRUNC | MSG_CTRUNC)) != 0) {
        errno = EMSGSIZE;
        return false;
    }
    return true;
}

}  // namespace platform
}  // namespace robottestingframework
