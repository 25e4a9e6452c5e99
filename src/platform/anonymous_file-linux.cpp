// Linux: memfd_create, a file in memory that never had a path.
#include "platform/anonymous_file.h"

#include <sys/mman.h>

namespace robottestingframework {
namespace platform {

FileDescriptor makeAnonymousFile(const char* label) {
    return FileDescriptor(::memfd_create(label, MFD_CLOEXEC));
}

}  // namespace platform
}  // namespace robottestingframework
