// What identifies an existing file whatever the path that names it (links, `..`, case on
// Windows): how the runner tells that an output would replace one of its inputs.
#pragma once

#include <string>

namespace robottestingframework {
namespace platform {

// The file's identity (POSIX: its device and inode; Windows: its volume serial number and file
// index, since MinGW's stat gives every file inode 0), or "" when `path` names no file.
// `writtenThrough`, when given, is set for what is not a regular file (a FIFO, a device).
std::string fileIdentity(const std::string& path, bool* writtenThrough = nullptr);

}  // namespace platform
}  // namespace robottestingframework
