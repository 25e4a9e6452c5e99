#include "reporters/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "reporters/standard_output.h"

namespace robottestingframework {
namespace reporters {

namespace {

std::string folderOf(const std::string& path) {
    std::size_t slash = path.rfind('/');
    if (slash == std::string::npos) {
        return {};
    }
    return path.substr(0, slash + 1);
}

// The file a chain of symbolic links ends at (or `path` itself): it is that file that is
// written, and the links stay. Gives up after as many links as the system follows.
std::string followLinks(const std::string& path) {
    std::string target = path;
    for (int hops = 0; hops < 40; ++hops) {
        struct stat info {};
        if (::lstat(target.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) {
            return target;
        }
        std::vector<char> link(4096);
        const ssize_t size = ::readlink(target.c_str(), link.data(), link.size());
        if (size <= 0 || static_cast<std::size_t>(size) >= link.size()) {
            return target;
        }
        const std::string next(link.data(), static_cast<std::size_t>(size));
        target = next[0] == '/' ? next : folderOf(target) + next;
    }
    return target;
}

}  // namespace

std::string notAnOutputFile(const std::string& filename) {
    if (namesStandardOutput(filename)) {
        return {};  // whatever it is (a pipe, a socket under a service manager), it is written
    }
    struct stat info {};
    if (::stat(filename.c_str(), &info) != 0 || S_ISREG(info.st_mode) || S_ISFIFO(info.st_mode) ||
        S_ISCHR(info.st_mode)) {
        return {};
    }
    const char* kind = S_ISDIR(info.st_mode)    ? "a folder"
                       : S_ISBLK(info.st_mode)  ? "a block device"
                       : S_ISSOCK(info.st_mode) ? "a socket"
                                                : "not a regular file";
    return filename + " is " + kind +
           "; an output is a file (or a FIFO or a character device, written through)";
}

AtomicFile::~AtomicFile() {
    discard();
}

void AtomicFile::discard() {
    if (fd_ >= 0) {
        ::close(fd_);
        fd_ = -1;
    }
    if (!temporary_.empty()) {
        std::remove(temporary_.c_str());
        temporary_.clear();
    }
}

bool AtomicFile::open(const std::string& filename, std::string& error) {
    discard();
    filename_ = filename;
    writeErrno_ = 0;
    if (namesStandardOutput(filename)) {
        // "-" and /dev/stdout: the standard output as the runner was given it (a pipe too,
        // where /dev/stdout's link leads nowhere), written through.
        fd_ = openStandardOutput();
        if (fd_ < 0) {
            error = "cannot write " + filename + ": " + std::strerror(errno);
            return false;
        }
        return true;
    }
    const std::string target = followLinks(filename);
    struct stat info {};
    if (::stat(target.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
        if (!S_ISFIFO(info.st_mode) && !S_ISCHR(info.st_mode)) {
            error = "cannot write " + notAnOutputFile(target);
            return false;
        }
        // A FIFO or a device (/dev/stdout, /dev/null) is written as it is, never replaced.
        // Without O_NONBLOCK, opening a FIFO nobody reads would wait for ever.
        fd_ = ::open(target.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
        if (fd_ < 0) {
            const int code = errno;
            error = "cannot write " + filename + ": " +
                    (code == ENXIO ? std::string("no process reads this FIFO")
                                   : std::string(std::strerror(code)));
            return false;
        }
        ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
        return true;
    }
    target_ = target;
    temporary_ = target + ".tmp." + std::to_string(::getpid());
    fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0) {
        const int code = errno;
        temporary_.clear();  // not ours: nothing to remove
        error = "cannot write " + filename + ": " + std::strerror(code);
        return false;
    }
    return true;
}

bool AtomicFile::write(const char* data, std::size_t size) {
    if (fd_ < 0 || writeErrno_ != 0) {
        return false;
    }
    std::size_t done = 0;
    while (done < size) {
        const ssize_t wrote = ::write(fd_, data + done, size - done);
        if (wrote < 0 && errno == EINTR) {
            continue;
        }
        if (wrote <= 0) {
            writeErrno_ = wrote < 0 ? errno : EIO;
            return false;
        }
        done += static_cast<std::size_t>(wrote);
    }
    return true;
}

bool AtomicFile::commit(std::string& error) {
    if (fd_ < 0) {
        error = "cannot write " + filename_ + ": " + std::strerror(EBADF);
        return false;
    }
    int code = writeErrno_;
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && errno != EINTR && code == 0) {
        code = errno;
    }
    if (code != 0) {
        error = "cannot write " + filename_ + ": " + std::strerror(code);
        discard();
        return false;
    }
    if (!temporary_.empty() && std::rename(temporary_.c_str(), target_.c_str()) != 0) {
        error = "cannot rename a temporary file to " + filename_ + ": " + std::strerror(errno);
        discard();
        return false;
    }
    temporary_.clear();
    return true;
}

}  // namespace reporters
}  // namespace robottestingframework
