// Portable POSIX (macOS): a stream socket (fd_passing-portable.cpp frames its packets); a path
// longer than sockaddr_un holds is refused.
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

bool addressOf(const std::string& folder, const std::string& name, sockaddr_un& address,
               std::string& error) {
    address = sockaddr_un{};
    address.sun_family = AF_UNIX;
    const std::string path = folder + "/" + name;
    if (path.size() >= sizeof address.sun_path) {
        error = path + ": too long for a local socket (at most " +
                std::to_string(sizeof address.sun_path - 1) + " characters here)";
        return false;
    }
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    return true;
}

// A new socket (close-on-exec) and the address of `name` in `folder`, for listenLocal and
// connectLocal; invalid with `error` set when either cannot be had.
FileDescriptor newSocket(const std::string& folder, const std::string& name, sockaddr_un& address,
                         std::string& error) {
    if (!addressOf(folder, name, address, error)) {
        return FileDescriptor();
    }
    FileDescriptor socket(::socket(AF_UNIX, SOCK_STREAM, 0));
    if (!socket.valid()) {
        error = std::string("socket: ") + std::strerror(errno);
    } else {
        setCloseOnExec(socket.get());
    }
    return socket;
}

}  // namespace

FileDescriptor listenLocal(const std::string& folder, const std::string& name, std::string& error) {
    sockaddr_un address;
    FileDescriptor socket = newSocket(folder, name, address, error);
    if (!socket.valid()) {
        return socket;
    }
    ::unlink(address.sun_path);
    if (::bind(socket.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 ||
        ::listen(socket.get(), 16) != 0) {
        error = folder + "/" + name + ": " + std::strerror(errno);
        return FileDescriptor();
    }
    return socket;
}

FileDescriptor acceptLocal(int listener) {
    int fd;
    do {
        fd = ::accept(listener, nullptr, nullptr);
    } while (fd < 0 && errno == EINTR);
    if (fd >= 0) {
        setCloseOnExec(fd);
    }
    return FileDescriptor(fd);
}

FileDescriptor connectLocal(const std::string& folder, const std::string& name,
                            std::string& error) {
    sockaddr_un address;
    FileDescriptor socket = newSocket(folder, name, address, error);
    if (!socket.valid()) {
        return socket;
    }
    int status;
    do {
        status =
            ::connect(socket.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address);
    } while (status != 0 && errno == EINTR);
    if (status != 0) {
        error = folder + "/" + name + ": " + std::strerror(errno);
        return FileDescriptor();
    }
    return socket;
}

}  // namespace platform
}  // namespace robottestingframework
