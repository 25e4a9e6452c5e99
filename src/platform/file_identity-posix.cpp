// POSIX: stat's device and inode.
#include "platform/file_identity.h"

#include <sys/stat.h>

namespace robottestingframework {
namespace platform {

std::string fileIdentity(const std::string& path, bool* writtenThrough) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) {
        return {};
    }
    if (writtenThrough != nullptr) {
        *writtenThrough = !S_ISREG(info.st_mode);
    }
    return std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
}

}  // namespace platform
}  // namespace robottestingframework
