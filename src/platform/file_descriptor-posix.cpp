#include "platform/file_descriptor.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include "platform/sigpipe_guard.h"

namespace robottestingframework {
namespace platform {

void FileDescriptor::reset(int fd) {
    if (fd_ >= 0) {
        ::close(fd_);
    }
    fd_ = fd;
}

void setNonBlocking(int fd, bool on) {
    int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) {
        ::fcntl(fd, F_SETFL, on ? (flags | O_NONBLOCK) : (flags & ~O_NONBLOCK));
    }
}

void setNewNonBlocking(int fd) {
    ::fcntl(fd, F_SETFL, O_NONBLOCK);
}

void setCloseOnExec(int fd, bool on) {
    int flags = ::fcntl(fd, F_GETFD);
    if (flags >= 0) {
        ::fcntl(fd, F_SETFD, on ? (flags | FD_CLOEXEC) : (flags & ~FD_CLOEXEC));
    }
}

namespace {

// Writes all of [p, p + size) with `put` (write or send), waiting while the other end is full.
template <typename Put>
bool putAll(int fd, const char* p, std::size_t size, Put put) {
    while (size > 0) {
        ssize_t n = put(fd, p, size);
        if (n > 0) {
            p += n;
            size -= static_cast<std::size_t>(n);
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            pollfd pfd{fd, POLLOUT, 0};
            ::poll(&pfd, 1, 100);
        } else {
            return false;
        }
    }
    return true;
}

}  // namespace

bool writeAll(int fd, const void* data, std::size_t size) {
    // send() with MSG_NOSIGNAL would only work on sockets; writers ignore SIGPIPE instead.
    return putAll(fd, static_cast<const char*>(data), size,
                  [](int to, const char* p, std::size_t n) { return ::write(to, p, n); });
}

bool sendAll(int socket, const std::string& data) {
    SigpipeGuard guard;
    return putAll(socket, data.data(), data.size(), [](int to, const char* p, std::size_t n) {
        return ::send(to, p, n, noSigpipeSendFlags());
    });
}

long readSome(int fd, std::string& out, std::size_t max) {
    char buffer[65536];
    if (max > sizeof(buffer)) {
        max = sizeof(buffer);
    }
    for (;;) {
        ssize_t n = ::read(fd, buffer, max);
        if (n > 0) {
            out.append(buffer, static_cast<std::size_t>(n));
            return n;
        }
        if (n == 0) {
            return 0;
        }
        if (errno != EINTR) {
            return -1;
        }
    }
}

bool waitReadable(const std::vector<int>& fds, int timeoutMs, std::vector<bool>& ready) {
    std::vector<pollfd> pfds(fds.size());
    for (std::size_t i = 0; i < fds.size(); ++i) {
        pfds[i] = pollfd{fds[i], POLLIN, 0};
    }
    ready.assign(fds.size(), false);
    int n;
    do {
        n = ::poll(pfds.data(), pfds.size(), timeoutMs);
    } while (n < 0 && errno == EINTR);
    if (n <= 0) {
        return false;
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
        ready[i] = fds[i] >= 0 && (pfds[i].revents & (POLLIN | POLLHUP | POLLERR)) != 0;
    }
    return true;
}

}  // namespace platform
}  // namespace robottestingframework
