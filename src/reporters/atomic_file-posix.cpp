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

bool AtomicFile::openFile(const std::string& filename, std::string& error) {
    const std::string target = followLinks(filename);
    struct stat info {};
    if (::stat(target.c_str(), &info) != 0 || S_ISREG(info.st_mode)) {
        return openTemporary(target, error);
    }
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

int AtomicFile::createFile(const std::string& path) {
    return ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
}

long AtomicFile::writeSome(int fd, const char* data, std::size_t size) {
    for (;;) {
        const ssize_t wrote = ::write(fd, data, size);
        if (wrote >= 0 || errno != EINTR) {
            return static_cast<long>(wrote);
        }
    }
}

int AtomicFile::closeFile(int fd) {
    // Interrupted, the descriptor is closed all the same (Linux, macOS): not a failure.
    return ::close(fd) != 0 && errno != EINTR ? -1 : 0;
}

std::string AtomicFile::processId() {
    return std::to_string(::getpid());
}

std::string AtomicFile::replaceFile(const std::string& temporary, const std::string& target) {
    if (std::rename(temporary.c_str(), target.c_str()) != 0) {
        return std::strerror(errno);
    }
    return {};
}

}  // namespace reporters
}  // namespace robottestingframework
