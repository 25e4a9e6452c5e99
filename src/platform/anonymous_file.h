// A file with no name in any folder, for data handed to another process with its descriptor.
#pragma once

#include <string>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

// An empty, unlinked, close-on-exec file open for reading and writing; invalid (errno set) on
// failure. `label` names it where the system keeps names for debugging.
FileDescriptor makeAnonymousFile(const char* label);

// An anonymous file holding `data` (read from its start by whoever receives it); invalid on
// failure.
FileDescriptor anonymousFileHolding(const std::string& data);
// The whole content of `file`, from its start. False on a read error.
bool readAnonymousFile(int file, std::string& data);

}  // namespace platform
}  // namespace robottestingframework
