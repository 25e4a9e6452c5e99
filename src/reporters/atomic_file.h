// Writing a report file whole or not at all: a temporary name beside it, then a rename. A
// symbolic link is followed (its target is written, the link stays); a FIFO or a character
// device (/dev/stdout, /dev/null) is written through, never replaced; anything else that is not
// a regular file (a folder, a socket) is refused.
#pragma once

#include <string>

#include <robottestingframework/TestMessage.h>

namespace robottestingframework {
namespace reporters {

// Empty when `filename` can be an output (a file, a FIFO, a character device, or nothing yet);
// else "FILE is a folder; ..." for the runner to refuse before the run.
std::string notAnOutputFile(const std::string& filename);

// On failure returns false, leaves no file behind and puts the file name and the system's
// reason in `error`.
bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error);

// What the outputters' write() does: the same, with the reason in `error` when given, on
// stderr otherwise.
bool writeReport(const std::string& filename, const std::string& content, TestMessage* error);

}  // namespace reporters
}  // namespace robottestingframework
