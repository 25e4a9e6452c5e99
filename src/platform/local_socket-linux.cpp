// Linux: SOCK_SEQPACKET, and long paths through the folder's descriptor (/proc/self/fd/N).
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "platform/local_socket.h"

namespace robottestingframework {
namespace platform {

namespace {

// Calls `use` with an address for folder/name; false with `error` when none can be made.
template <typename Use>
bool withAddress(const std::string& folder, const std::string& name, std::string& error, Use use) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::string path = folder + "/" + name;
    FileDescriptor folderFd;
    if (path.size() >= sizeof address.sun_path) {
        folderFd.reset(::open(folder.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC));
        if (!folderFd.valid()) {
            error = folder + ": " + std::strerror(errno);
            return false;
        }
        path = "/proc/self/fd/" + std::to_string(folderFd.get()) + "/" + name;
        if (path.size() >= sizeof address.sun_path) {
            error = name + ": name too long for a local socket";
            return false;
        }
    }
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    return use(reinterpret_cast<const sockaddr*>(&address), sizeof address, path);
}

}  // namespace

FileDescriptor listenLocal(const std::string& folder, const std::string& name, std::string& error) {
    FileDescriptor socket(::socket(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0));
    if (!socket.valid()) {
        error = std::string("socket: ") + std::strerror(errno);
        return FileDescriptor();
    }
    const bool bound = withAddress(
        folder, name, error, [&](const sockaddr* address, socklen_t size, const std::string& at) {
            ::unlink(at.c_str());
            if (::bind(socket.get(), address, size) != 0 || ::listen(socket.get(), 16) != 0) {
                error = folder + "/" + name + ": " + std::strerror(errno);
                return false;
            }
            return true;
        });
    return bound ? std::move(socket) : FileDescriptor();
}

FileDescriptor acceptLocal(int listener) {
    int fd;
    do {
        fd = ::accept4(listener, nullptr, nullptr, SOCK_CLOEXEC);
    } while (fd < 0 && errno == EINTR);
    return FileDescriptor(fd);
}

FileDescriptor connectLocal(const std::string& folder, const std::string& name,
                            std::string& error) {
    FileDescriptor socket(::socket(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0));
    if (!socket.valid()) {
        error = std::string("socket: ") + std::strerror(errno);
        return FileDescriptor();
    }
    const bool connected = withAddress(
        folder, name, error, [&](const sockaddr* address, socklen_t size, const std::string&) {
            int status;
            do {
                status = ::connect(socket.get(), address, size);
            } while (status != 0 && errno == EINTR);
            if (status != 0) {
                error = folder + "/" + name + ": " + std::strerror(errno);
                return false;
            }
            return true;
        });
    return connected ? std::move(socket) : FileDescriptor();
}

}  // namespace platform
}  // namespace robottestingframework
