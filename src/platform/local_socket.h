// A named local socket (AF_UNIX) in a folder, for a process to find another by a path: a
// world keeper's control socket (runner/cli/world_keeper.h). Packets keep their boundaries as
// sendWithFds/receiveWithFds need (SOCK_SEQPACKET on Linux; a stream they frame in the
// portable build). A path longer than sockaddr_un holds is reached through the folder's
// descriptor on Linux (/proc/self/fd/N/NAME); the portable build says it is too long.
// One file per platform: -linux, -portable (none on Windows).
#pragma once

#include <string>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

// Listens at `folder`/`name`, replacing a socket left there. Invalid with `error`.
FileDescriptor listenLocal(const std::string& folder, const std::string& name, std::string& error);
// The next connection on `listener` (close-on-exec); invalid on error (errno set).
FileDescriptor acceptLocal(int listener);
// Connects to `folder`/`name`. Invalid with `error` (nobody listens there, no such file).
FileDescriptor connectLocal(const std::string& folder, const std::string& name, std::string& error);

}  // namespace platform
}  // namespace robottestingframework
