// Portable POSIX: macOS has neither SOCK_SEQPACKET for local sockets nor MSG_CMSG_CLOEXEC. A
// message is framed on a stream socket (makeSocketPair gives one): a kind byte and a 4-byte
// length, then the bytes; its descriptors travel with the frame's first byte and are made
// close-on-exec once received.
#include "platform/fd_passing.h"

#include <errno.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>

#include "platform/scm_rights.h"

namespace robottestingframework {
namespace platform {

namespace {

using fd_passing::kInFile;
using fd_passing::kInline;

// A frame: its kind's byte (fd_passing.h), the body's length, the body.
constexpr std::size_t kHeader = 1 + sizeof(std::uint32_t);

// Reads exactly `size` bytes into `out`; false at end of stream or on error.
bool readExactly(int socket, char* out, std::size_t size) {
    while (size > 0) {
        ssize_t n = ::read(socket, out, size);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            return false;
        }
        out += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

bool fd_passing::sendMessage(int socket, char kind, const std::string& body,
                             const std::vector<int>& fds) {
    std::string frame(1, kind);
    const std::uint32_t length = static_cast<std::uint32_t>(body.size());
    frame.append(reinterpret_cast<const char*>(&length), sizeof(length));
    frame += body;
    const ssize_t n = sendWithRights(socket, frame.data(), frame.size(), fds);
    if (n < 0) {
        return false;
    }
    // A stream takes what fits: the rest follows without descriptors.
    return sendAll(socket, frame.substr(static_cast<std::size_t>(n)));
}

bool receiveWithFds(int socket, std::string& data, std::vector<FileDescriptor>& fds) {
    fds.clear();
    data.clear();
    // The header alone, so that the descriptors of the next frame stay with it.
    char header[kHeader];
    int flags = 0;
    const ssize_t n = receiveWithRights(socket, header, sizeof(header), MSG_WAITALL, fds, flags);
    for (const FileDescriptor& fd : fds) {
        setCloseOnExec(fd.get());
    }
    if (n <= 0) {
        return false;
    }
    if (static_cast<std::size_t>(n) < kHeader &&
        !readExactly(socket, header + n, kHeader - static_cast<std::size_t>(n))) {
        return false;
    }
    std::uint32_t length = 0;
    std::memcpy(&length, header + 1, sizeof(length));
    const char kind = header[0];
    if ((flags & MSG_CTRUNC) != 0 || (kind != kInline && kind != kInFile) ||
        (kind == kInFile && fds.empty()) || length >= kMaxPacket) {
        errno = EMSGSIZE;
        return false;
    }
    data.resize(length);
    if (length > 0 && !readExactly(socket, &data[0], length)) {
        data.clear();
        return false;
    }
    if (kind == kInline) {
        return true;
    }
    return fd_passing::readMessageFile(fds, data);
}

}  // namespace platform
}  // namespace robottestingframework
