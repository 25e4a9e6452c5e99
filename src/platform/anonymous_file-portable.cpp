// Portable POSIX (macOS has no memfd_create): mkstemp in $TMPDIR, unlinked at once, so the
// file lives only as long as its descriptors.
#include "platform/anonymous_file.h"

#include <stdlib.h>
#include <unistd.h>

#include <string>

namespace robottestingframework {
namespace platform {

FileDescriptor makeAnonymousFile(const char* label) {
    const char* folder = ::getenv("TMPDIR");
    std::string path = folder != nullptr && *folder != '\0' ? folder : "/tmp";
    path += std::string("/") + label + "-XXXXXX";
    FileDescriptor file(::mkstemp(&path[0]));
    if (file.valid()) {
        ::unlink(path.c_str());
        setCloseOnExec(file.get());
    }
    return file;
}

}  // namespace platform
}  // namespace robottestingframework
