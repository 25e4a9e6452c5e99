#include "platform/anonymous_file.h"

#include <errno.h>
#include <sys/stat.h>
#include <unistd.h>

namespace robottestingframework {
namespace platform {

FileDescriptor anonymousFileHolding(const std::string& data) {
    FileDescriptor file = makeAnonymousFile("rtf-message");
    if (!file.valid() || !writeAll(file.get(), data)) {
        return FileDescriptor();
    }
    return file;
}

bool readAnonymousFile(int file, std::string& data) {
    struct stat info {};
    if (::fstat(file, &info) != 0) {
        return false;
    }
    data.resize(static_cast<std::size_t>(info.st_size));
    std::size_t done = 0;
    while (done < data.size()) {
        ssize_t n = ::pread(file, &data[done], data.size() - done, static_cast<off_t>(done));
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace platform
}  // namespace robottestingframework
