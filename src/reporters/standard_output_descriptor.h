// The descriptor calls the standard output of reports needs, one file per platform
// (standard_output_descriptor-posix.cpp, -windows.cpp); reporters/standard_output.cpp uses them.
#pragma once

namespace robottestingframework {
namespace reporters {

constexpr int standardOutputDescriptor = 1;
constexpr int standardErrorDescriptor = 2;

// A new descriptor on `fd` (not inherited by children where the platform allows); -1 with errno
// set on failure.
int duplicateDescriptor(int fd);
// Points `target` at what `source` is open on; false with errno set on failure.
bool pointDescriptor(int source, int target);
void closeDescriptor(int fd);

}  // namespace reporters
}  // namespace robottestingframework
