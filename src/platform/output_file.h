// The file a process points its descriptors 1 and 2 at to catch what it prints (child processes
// included), and the descriptor operations that pointing and reading back take. The runner's
// output capture (runner/execution/output_capture.cpp) is written once on these.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

// An empty temporary file, open for reading and appending, not inherited by child processes,
// that goes away when its last descriptor closes (unlinked at once on POSIX, in $TMPDIR;
// delete-on-close on Windows). Invalid with `error` set on failure.
FileDescriptor makeOutputFile(std::string& error);

// Flushes std::cout, std::cerr and C's stdout and stderr: what they hold goes where
// descriptors 1 and 2 point now, before they are pointed (or copied) elsewhere.
void flushStandardStreams();

// A copy of `fd`, not inherited, numbered 3 or above; -1 (errno set) on failure.
int copyDescriptor(int fd);
// Makes descriptor `target` refer to what `fd` refers to. False (errno set) on failure.
bool pointDescriptor(int fd, int target);
void closeDescriptor(int fd);
// A C stream writing to `fd` (which it then owns); nullptr on failure.
std::FILE* writeStreamOn(int fd);

// The size of a file only ever appended to (its end); -1 on error.
long long outputFileSize(int fd);
// Reads up to `size` bytes at `offset` into `data`; the number read (short only at the end or
// on an error).
std::size_t readOutputFile(int fd, long long offset, char* data, std::size_t size);
// Empties the file; appending starts again at its beginning. False on failure.
bool emptyOutputFile(int fd);

}  // namespace platform
}  // namespace robottestingframework
