#include "web/whole_answer.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace robottestingframework {
namespace web {

namespace {

// The address and port of `address`, as the web server writes them ("127.0.0.1", 41234).
bool named(const sockaddr_storage& address, const std::string& host, int port) {
    char text[INET6_ADDRSTRLEN] = {};
    int actualPort = -1;
    if (address.ss_family == AF_INET) {
        const auto& in = reinterpret_cast<const sockaddr_in&>(address);
        ::inet_ntop(AF_INET, &in.sin_addr, text, sizeof text);
        actualPort = ntohs(in.sin_port);
    } else if (address.ss_family == AF_INET6) {
        const auto& in6 = reinterpret_cast<const sockaddr_in6&>(address);
        ::inet_ntop(AF_INET6, &in6.sin6_addr, text, sizeof text);
        actualPort = ntohs(in6.sin6_port);
    } else {
        return false;
    }
    return actualPort == port && host == text;
}

// The descriptor of the connection, or -1. The server does not hand it to its handlers; a
// run's process has a few dozen descriptors, and this is asked only by RTF 2.x's clients.
int connectionDescriptor(const std::string& localAddress, int localPort,
                         const std::string& remoteAddress, int remotePort) {
    const long most = ::sysconf(_SC_OPEN_MAX);
    const int last = most > 0 && most < 65536 ? static_cast<int>(most) : 65536;
    for (int fd = 0; fd < last; ++fd) {
        sockaddr_storage local{};
        sockaddr_storage remote{};
        socklen_t localSize = sizeof local;
        socklen_t remoteSize = sizeof remote;
        if (::getsockname(fd, reinterpret_cast<sockaddr*>(&local), &localSize) == 0 &&
            named(local, localAddress, localPort) &&
            ::getpeername(fd, reinterpret_cast<sockaddr*>(&remote), &remoteSize) == 0 &&
            named(remote, remoteAddress, remotePort)) {
            return fd;
        }
    }
    return -1;
}

}  // namespace

void holdAnswerUntilClosed(const std::string& localAddress, int localPort,
                           const std::string& remoteAddress, int remotePort) {
    const int fd = connectionDescriptor(localAddress, localPort, remoteAddress, remotePort);
    if (fd < 0) {
        return;
    }
    const int on = 1;
#if defined(TCP_CORK)
    ::setsockopt(fd, IPPROTO_TCP, TCP_CORK, &on, sizeof on);
#elif defined(TCP_NOPUSH)
    ::setsockopt(fd, IPPROTO_TCP, TCP_NOPUSH, &on, sizeof on);
#endif
}

}  // namespace web
}  // namespace robottestingframework
