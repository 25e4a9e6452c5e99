// Owned file descriptors, pipes and socket pairs, and the read/write/poll loops around them
// (EINTR and short writes handled once, here).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace robottestingframework {
namespace platform {

class FileDescriptor {
public:
    FileDescriptor() = default;
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() { reset(); }
    FileDescriptor(FileDescriptor&& other) noexcept : fd_(other.release()) {}
    FileDescriptor& operator=(FileDescriptor&& other) noexcept;
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;

    int get() const { return fd_; }
    bool valid() const { return fd_ >= 0; }
    int release();
    void reset(int fd = -1);

private:
    int fd_ = -1;
};

// Both ends close-on-exec. False (errno set) on failure.
bool makePipe(FileDescriptor& readEnd, FileDescriptor& writeEnd);
// A connected pair of local sockets; `packets`: for sendWithFds/receiveWithFds, which keep
// message boundaries (SOCK_SEQPACKET on Linux; a stream they frame in the portable build).
bool makeSocketPair(FileDescriptor& first, FileDescriptor& second, bool packets);

// Closes every descriptor numbered `first` or above (in a child before it runs other code:
// async-signal-safe).
void closeDescriptorsFrom(int first);

// The flags for send() and sendmsg() that keep SIGPIPE away when the peer is gone
// (MSG_NOSIGNAL); 0 where the system has none, and the caller ignores SIGPIPE. A function, not
// a global: the platform code is linked into several shared libraries of one process, and a
// global defined in each is one name given twice (ASan's ODR check stops the program).
int noSigpipeSendFlags();

void setNonBlocking(int fd, bool on = true);
// The same for a descriptor just made (a pipe's or a socket pair's end: no other status flag
// set), in one system call instead of two.
void setNewNonBlocking(int fd);
void setCloseOnExec(int fd, bool on = true);

// Writes everything (waiting while a non-blocking fd is full). False when the reader is gone.
bool writeAll(int fd, const void* data, std::size_t size);
inline bool writeAll(int fd, const std::string& data) {
    return writeAll(fd, data.data(), data.size());
}

// The same on a stream socket, without SIGPIPE when the peer is gone.
bool sendAll(int socket, const std::string& data);

// One read: >0 bytes appended to `out`, 0 at end of file, -1 when nothing is available now
// (non-blocking fd) or on error (errno tells).
long readSome(int fd, std::string& out, std::size_t max = 65536);

// Waits until one of `fds` is readable (or hung up), at most `timeoutMs` (-1: forever).
// `ready[i]` tells which; returns false on timeout. Negative fds are ignored.
bool waitReadable(const std::vector<int>& fds, int timeoutMs, std::vector<bool>& ready);

}  // namespace platform
}  // namespace robottestingframework
