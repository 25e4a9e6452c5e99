#include "platform/file_claim.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace robottestingframework {
namespace platform {

bool FileClaim::take(const std::string& path, bool& busy, std::string& error) {
    release();
    busy = false;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
        error = std::strerror(errno);
        return false;
    }
    int locked = 0;
    do {
        locked = ::flock(fd, LOCK_EX | LOCK_NB);
    } while (locked != 0 && errno == EINTR);
    if (locked != 0) {
        const int why = errno;
        ::close(fd);
        if (why == EWOULDBLOCK) {
            busy = true;
        } else {
            error = std::strerror(why);
        }
        return false;
    }
    handle_ = fd;
    return true;
}

void FileClaim::release() {
    if (handle_ != -1) {
        ::close(static_cast<int>(handle_));  // lets the lock go
        handle_ = -1;
    }
}

}  // namespace platform
}  // namespace robottestingframework
