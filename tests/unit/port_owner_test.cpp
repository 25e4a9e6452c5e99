// Whose listener a <port> check reached (Linux: /proc/net/tcp{,6} and /proc/<pid>/fd).
#include "fixtures/process/port_owner.h"

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include <gtest/gtest.h>

using namespace robottestingframework::fixtures;

namespace {

// A TCP socket listening on a free port of 127.0.0.1, held by this process.
class Listener {
public:
    Listener() {
        fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        ::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address);
        ::listen(fd_, 4);
        socklen_t size = sizeof address;
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &size);
        port_ = ntohs(address.sin_port);
    }
    ~Listener() { ::close(fd_); }
    int port() const { return port_; }

private:
    int fd_ = -1;
    int port_ = 0;
};

}  // namespace

TEST(PortOwner, OursWhenTheListenerIsInTheProcessGroup) {
    Listener listener;
    std::string holder;
    EXPECT_EQ(portOwner("127.0.0.1", listener.port(), static_cast<int>(::getpgrp()), "", holder),
              PortOwner::Ours);
    EXPECT_EQ(portOwner("localhost", listener.port(), static_cast<int>(::getpgrp()), "", holder),
              PortOwner::Ours);
}

TEST(PortOwner, OursWhenTheListenerCarriesTheWorldsMarker) {
    // An entry of this process's environment as the kernel shows it (a daemon of the world
    // that left its group still carries the world's marker).
    std::ifstream in("/proc/self/environ", std::ios::binary);
    std::string entry;
    ASSERT_TRUE(std::getline(in, entry, '\0'));
    Listener listener;
    std::string holder;
    EXPECT_EQ(portOwner("127.0.0.1", listener.port(), -1, entry, holder), PortOwner::Ours);
}

TEST(PortOwner, ForeignNamesTheHolder) {
    Listener listener;
    std::string holder;
    EXPECT_EQ(portOwner("127.0.0.1", listener.port(), -1, "RTF_NO_SUCH_MARKER=1", holder),
              PortOwner::Foreign);
    EXPECT_EQ(holder.rfind("pid " + std::to_string(::getpid()) + " (", 0), 0u) << holder;
}

TEST(PortOwner, UnknownWhenNothingListensOrTheHostIsAnotherMachine) {
    std::string holder;
    int port = 0;
    {
        Listener closed;
        port = closed.port();
    }
    EXPECT_EQ(portOwner("127.0.0.1", port, -1, "", holder), PortOwner::Unknown);
    Listener listener;
    // TEST-NET-1 (RFC 5737): never this machine's.
    EXPECT_EQ(portOwner("192.0.2.1", listener.port(), -1, "", holder), PortOwner::Unknown);
}
