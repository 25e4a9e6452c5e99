#include "platform/scm_rights.h"

#include <errno.h>
#include <sys/socket.h>
#include <sys/uio.h>

#include <cstring>

#include "platform/fd_passing.h"
#include "platform/file_descriptor.h"
#include "platform/sigpipe_guard.h"

namespace robottestingframework {
namespace platform {

namespace {

// Room for the most descriptors a message carries, and the file of a long one.
constexpr std::size_t kMostRights = kMaxPassedFds + 1;

}  // namespace

ssize_t sendWithRights(int socket, const char* data, std::size_t size,
                       const std::vector<int>& fds) {
    if (fds.size() > kMostRights) {
        errno = EMSGSIZE;
        return -1;
    }
    iovec iov{};
    iov.iov_base = const_cast<char*>(data);
    iov.iov_len = size;
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int) * kMostRights)];
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
    SigpipeGuard guard;
    ssize_t n;
    do {
        n = ::sendmsg(socket, &msg, noSigpipeSendFlags());
    } while (n < 0 && errno == EINTR);
    return n;
}

ssize_t receiveWithRights(int socket, char* buffer, std::size_t size, int flags,
                          std::vector<FileDescriptor>& fds, int& messageFlags) {
    iovec iov{};
    iov.iov_base = buffer;
    iov.iov_len = size;
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int) * kMostRights)];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof(control);
    ssize_t n;
    do {
        n = ::recvmsg(socket, &msg, flags);
    } while (n < 0 && errno == EINTR);
    messageFlags = n >= 0 ? msg.msg_flags : 0;
    if (n <= 0 || msg.msg_controllen == 0) {
        return n;
    }
    for (cmsghdr* header = CMSG_FIRSTHDR(&msg); header != nullptr;
         header = CMSG_NXTHDR(&msg, header)) {
        if (header->cmsg_level == SOL_SOCKET && header->cmsg_type == SCM_RIGHTS) {
            const std::size_t count = (header->cmsg_len - CMSG_LEN(0)) / sizeof(int);
            for (std::size_t i = 0; i < count; ++i) {
                int fd;
                std::memcpy(&fd, CMSG_DATA(header) + i * sizeof(int), sizeof(int));
                fds.emplace_back(fd);
            }
        }
    }
    return n;
}

}  // namespace platform
}  // namespace robottestingframework
