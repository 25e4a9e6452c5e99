// Sending open file descriptors to another process along with a message, over a local
// packet socket (SCM_RIGHTS on POSIX). How the runner hands a test's pipes to the fork server.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

// The largest packet on the socket. A longer message travels in an anonymous file whose
// descriptor goes with the packet, so a message may have any size.
constexpr std::size_t kMaxPacket = 128 * 1024;
// The most descriptors one message carries.
constexpr std::size_t kMaxPassedFds = 8;

// Sends `data` and duplicates of `fds` as one packet. False on error (errno set).
bool sendWithFds(int socket, const std::string& data, const std::vector<int>& fds);

// Receives one packet: its bytes and the descriptors it carried (close-on-exec). Returns false
// at end of stream (the peer is gone) or on error; an empty packet is not end of stream.
bool receiveWithFds(int socket, std::string& data, std::vector<FileDescriptor>& fds);

// What fd_passing-posix.cpp (shared) and fd_passing-<variant>.cpp (the framing) tell each other.
namespace fd_passing {

// A message's first byte: the message follows in the packet, or it is in the file passed as the
// packet's last descriptor (a message longer than a packet can be).
constexpr char kInline = 'i';
constexpr char kInFile = 'f';

// Sends one message of `kind` with `body` and `fds` (per variant).
bool sendMessage(int socket, char kind, const std::string& body, const std::vector<int>& fds);
// A kInFile message's bytes, read from its file (the last of `fds`, taken from them). False
// with errno EMSGSIZE when it cannot be read.
bool readMessageFile(std::vector<FileDescriptor>& fds, std::string& data);

}  // namespace fd_passing

}  // namespace platform
}  // namespace robottestingframework
