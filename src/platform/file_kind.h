// What a path is, in the words of the messages that refuse an input of the wrong kind ("PATH:
// is a character device, not a suite file"): one wording for the suite files, reports,
// history files and plug-ins.
#pragma once

#include <filesystem>

namespace robottestingframework {
namespace platform {

// "a folder", "a FIFO (named pipe)", "a character device", "a block device", "a socket",
// "a regular file", else "not a regular file".
const char* fileKindText(std::filesystem::file_type type);

}  // namespace platform
}  // namespace robottestingframework
