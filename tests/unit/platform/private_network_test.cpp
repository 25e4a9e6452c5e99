// platform/private_network.h on Linux: each network has its own loopback, up, where a fixed
// port binds however many networks bind it; a process joins one (as root directly, as another
// user through its user namespace), a thread joins one and comes back. Prints (never asserts)
// what making one costs.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>

#include "platform/file_descriptor.h"
#include "platform/private_network.h"

using robottestingframework::platform::FileDescriptor;
using robottestingframework::platform::joinPrivateNetwork;
using robottestingframework::platform::PrivateNetwork;
using robottestingframework::platform::ThreadInNetwork;

namespace {

// A port no one uses on this machine's loopback now.
int freePort() {
    FileDescriptor s(::socket(AF_INET, SOCK_STREAM, 0));
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (::bind(s.get(), reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::getsockname(s.get(), reinterpret_cast<sockaddr*>(&address), &length) != 0) {
        return -1;
    }
    return ntohs(address.sin_port);
}

// A socket listening on 127.0.0.1:`port` in the calling thread's network; invalid when it
// cannot (the port is taken, or loopback is down).
FileDescriptor listenOn(int port) {
    FileDescriptor s(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::bind(s.get(), reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::listen(s.get(), 4) != 0) {
        return FileDescriptor();
    }
    return s;
}

// True when 127.0.0.1:`port` accepts a connection in the calling thread's network.
bool connects(int port) {
    FileDescriptor s(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return ::connect(s.get(), reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
}

// Runs `body` in a forked child (a process with one thread, as a worker is); its exit status:
// 0 when `body` returned true.
int inChild(const std::function<bool()>& body) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::_exit(body() ? 0 : 1);
    }
    int status = -1;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + WTERMSIG(status);
}

// In a child: joins `network`, then `port` binds (though this machine's loopback holds it) and
// accepts a connection there.
bool bindsAndConnectsIn(const PrivateNetwork& network, int port) {
    std::string error;
    if (!joinPrivateNetwork(network.descriptors(), error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return false;
    }
    FileDescriptor listening = listenOn(port);
    return listening.valid() && connects(port);
}

}  // namespace

TEST(PrivateNetwork, AFixedPortBindsInEachNetworkWhileThisMachineHoldsIt) {
    const int port = freePort();
    ASSERT_GT(port, 0);
    FileDescriptor held = listenOn(port);
    ASSERT_TRUE(held.valid());
    ASSERT_FALSE(listenOn(port).valid()) << "the port is taken here, as a second world finds it";

    std::string error;
    auto first = PrivateNetwork::create(error);
    ASSERT_TRUE(first) << error;
    auto second = PrivateNetwork::create(error);
    ASSERT_TRUE(second) << error;
    EXPECT_EQ(inChild([&] { return bindsAndConnectsIn(*first, port); }), 0);
    EXPECT_EQ(inChild([&] { return bindsAndConnectsIn(*second, port); }), 0);
    // Two processes in one network share it: the second finds the port the first holds.
    EXPECT_EQ(inChild([&] {
                  std::string why;
                  if (!joinPrivateNetwork(first->descriptors(), why)) {
                      return false;
                  }
                  FileDescriptor mine = listenOn(port);
                  return mine.valid() && inChild([&] { return !listenOn(port).valid(); }) == 0;
              }),
              0);
}

TEST(PrivateNetwork, AnotherUserHasOneThroughAUserNamespace) {
    const int port = freePort();
    ASSERT_GT(port, 0);
    FileDescriptor held = listenOn(port);
    ASSERT_TRUE(held.valid());
    // As root, the child becomes "nobody" first: the way every other user has one.
    const int status = inChild([&] {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) {
            return false;
        }
        std::string error;
        auto network = PrivateNetwork::create(error);
        if (!network) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return false;
        }
        // A user namespace to join first; a thread of a process cannot.
        if (network->descriptors().size() != 2 || network->joinableByThread()) {
            return false;
        }
        ThreadInNetwork thread;
        if (thread.enter(*network, error) || error.find("user namespace") == std::string::npos) {
            return false;
        }
        return inChild([&] { return bindsAndConnectsIn(*network, port); }) == 0;
    });
    EXPECT_EQ(status, 0);
}

TEST(PrivateNetwork, AThreadJoinsOneAndComesBack) {
    if (::geteuid() != 0) {
        // Another user's network is in a user namespace, which no thread of a process can join
        // (the test above checks that it says so).
        GTEST_SKIP() << "a thread joins a private network only as root";
    }
    const int port = freePort();
    ASSERT_GT(port, 0);
    FileDescriptor held = listenOn(port);
    ASSERT_TRUE(held.valid());
    std::string error;
    auto network = PrivateNetwork::create(error);
    ASSERT_TRUE(network) << error;
    ASSERT_TRUE(network->joinableByThread());
    bool inside = false, back = false, started = false;
    std::thread([&] {
        {
            ThreadInNetwork joined;
            ASSERT_TRUE(joined.enter(*network, error)) << error;
            FileDescriptor mine = listenOn(port);
            inside = mine.valid() && connects(port);
            // A thread started meanwhile starts in it.
            std::thread([&] { started = !listenOn(port).valid(); }).join();
        }
        back = !listenOn(port).valid();  // this machine's again: the port is held
    }).join();
    EXPECT_TRUE(inside);
    EXPECT_TRUE(started);
    EXPECT_TRUE(back);
}

TEST(PrivateNetwork, WhatMakingOneCosts) {
    // Printed for the record, never asserted: the time from asking to a network with loopback
    // up, and a process in it.
    constexpr int kCount = 20;
    double made = 0, joined = 0;
    for (int i = 0; i < kCount; ++i) {
        const auto start = std::chrono::steady_clock::now();
        std::string error;
        auto network = PrivateNetwork::create(error);
        ASSERT_TRUE(network) << error;
        const auto ready = std::chrono::steady_clock::now();
        EXPECT_EQ(inChild([&] {
                      std::string why;
                      return joinPrivateNetwork(network->descriptors(), why);
                  }),
                  0);
        const auto end = std::chrono::steady_clock::now();
        made += std::chrono::duration<double, std::milli>(ready - start).count();
        joined += std::chrono::duration<double, std::milli>(end - ready).count();
    }
    std::printf("a private network (%s): made in %.2f ms on average, a fork joining it %.2f ms\n",
                ::geteuid() == 0 ? "root: a network namespace" : "a user and a network namespace",
                made / kCount, joined / kCount);
}
