// What both POSIX variants share: a long message travels in an anonymous file, so a message
// costs the same whichever frames it (fd_passing-linux.cpp, fd_passing-portable.cpp).
#include "platform/fd_passing.h"

#include <errno.h>

#include "platform/anonymous_file.h"

namespace robottestingframework {
namespace platform {

bool sendWithFds(int socket, const std::string& data, const std::vector<int>& fds) {
    if (fds.size() > kMaxPassedFds) {
        errno = EMSGSIZE;
        return false;
    }
    if (data.size() < kMaxPacket) {
        return fd_passing::sendMessage(socket, fd_passing::kInline, data, fds);
    }
    FileDescriptor file = anonymousFileHolding(data);
    if (!file.valid()) {
        return false;
    }
    std::vector<int> withFile = fds;
    withFile.push_back(file.get());
    return fd_passing::sendMessage(socket, fd_passing::kInFile, {}, withFile);
}

bool fd_passing::readMessageFile(std::vector<FileDescriptor>& fds, std::string& data) {
    FileDescriptor file = std::move(fds.back());
    fds.pop_back();
    if (!readAnonymousFile(file.get(), data)) {
        errno = EMSGSIZE;
        return false;
    }
    return true;
}

}  // namespace platform
}  // namespace robottestingframework
