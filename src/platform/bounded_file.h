// Reading a whole input file the user names (a suite file, a report, a --var-file, ...) with its
// type checked and its size bounded: a FIFO nobody writes would block the run forever and a
// device (/dev/zero) would be read until memory runs out.
#pragma once

#include <cstddef>
#include <string>

namespace robottestingframework {
namespace platform {

// Whether a pipe is read as the file: the shell's `<(command)` names one (/dev/fd/63).
enum class Pipes { Refused, Read };

// Reads all of `path` into `content`: a regular file (or, with Pipes::Read, a pipe) of at most
// `limit` bytes. Else false with `error`, naming `path` and `what` it should be ("suite file"):
// "PATH: is a character device, not a suite file (a suite file is a regular file)", "PATH: the
// suite file is larger than 16 MiB, the limit of a suite file". A pipe is read once, to its end
// or one byte past `limit`.
bool readBoundedFile(const std::string& path, const std::string& what, std::size_t limit,
                     Pipes pipes, std::string& content, std::string& error);

}  // namespace platform
}  // namespace robottestingframework
