// A network of its own for a suite (<suite network="private">, --network private): a Linux
// network namespace with its loopback up, so that suites side by side bind the same fixed
// ports. Made directly when this process may (root), else inside a user namespace of its own.
// The namespaces live as long as a descriptor of them or a process in them: nothing outlives
// the run. Where there are none (the portable build, Windows), create() says why.
// One file per platform: -linux, -portable, -windows.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

class PrivateNetwork {
public:
    // A new network with its loopback up (and multicast on it). nullptr with `error` when it
    // cannot be had: the kernel's refusal and, where known, the setting that allows it.
    static std::unique_ptr<PrivateNetwork> create(std::string& error);

    PrivateNetwork(FileDescriptor user, FileDescriptor network)
        : user_(std::move(user)), network_(std::move(network)) {}

    // What a process joins, in order (joinPrivateNetwork): the user namespace when one was
    // needed, then the network namespace. Passed to a worker with its request (SCM_RIGHTS).
    std::vector<int> descriptors() const;
    // True when a thread of a running process can join it (no user namespace to join: the
    // runner is root), as --isolation none needs.
    bool joinableByThread() const { return !user_.valid(); }

private:
    FileDescriptor user_;     // invalid when made directly (root)
    FileDescriptor network_;  // the network namespace
};

// In a process with a single thread (a worker just forked): joins the namespaces that
// PrivateNetwork::descriptors() gave, for good. False with `error`.
bool joinPrivateNetwork(const std::vector<int>& descriptors, std::string& error);

// Moves the calling thread into a network and back when destroyed (network namespaces belong
// to threads on Linux; what the thread starts meanwhile starts in that network).
class ThreadInNetwork {
public:
    ThreadInNetwork() = default;
    ~ThreadInNetwork();
    ThreadInNetwork(const ThreadInNetwork&) = delete;
    ThreadInNetwork& operator=(const ThreadInNetwork&) = delete;

    // False with `error` (and the thread where it was) when it cannot.
    bool enter(const PrivateNetwork& network, std::string& error);

private:
    FileDescriptor home_;  // the thread's network before enter()
};

}  // namespace platform
}  // namespace robottestingframework
