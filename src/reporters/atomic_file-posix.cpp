#include "reporters/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

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

// A FIFO or a device (/dev/stdout, /dev/null) is written as it is, never replaced.
bool writeThrough(const std::string& filename, const std::string& target,
                  const std::string& content, std::string& error) {
    // Without O_NONBLOCK, opening a FIFO nobody reads would wait for ever.
    const int fd = ::open(target.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        const int code = errno;
        error = "cannot write " + filename + ": " +
                (code == ENXIO ? std::string("no process reads this FIFO")
                               : std::string(std::strerror(code)));
        return false;
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    std::size_t done = 0;
    while (done < content.size()) {
        const ssize_t wrote = ::write(fd, content.data() + done, content.size() - done);
        if (wrote < 0 && errno == EINTR) {
            continue;
        }
        if (wrote <= 0) {
            const int code = wrote < 0 ? errno : EIO;
            ::close(fd);
            error = "cannot write " + filename + ": " + std::strerror(code);
            return false;
        }
        done += static_cast<std::size_t>(wrote);
    }
    if (::close(fd) != 0 && errno != EINTR) {
        error = "cannot write " + filename + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

}  // namespace

std::string notAnOutputFile(const std::string& filename) {
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

bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error) {
    const std::string target = followLinks(filename);
    struct stat info {};
    if (::stat(target.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
        if (S_ISFIFO(info.st_mode) || S_ISCHR(info.st_mode)) {
            return writeThrough(filename, target, content, error);
        }
        error = "cannot write " + notAnOutputFile(target);
        return false;
    }
    const std::string temporary = target + ".tmp." + std::to_string(::getpid());
    auto fail = [&](const std::string& what, int code) {
        error = "cannot " + what + " " + filename + ": " + std::strerror(code);
        std::remove(temporary.c_str());
        return false;
    };
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr) {
        return fail("write", errno);
    }
    const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
    const int writeErrno = errno;
    if (std::fclose(file) != 0 || !written) {
        return fail("write", written ? errno : writeErrno);
    }
    if (std::rename(temporary.c_str(), target.c_str()) != 0) {
        return fail("rename a temporary file to", errno);
    }
    return true;
}

}  // namespace reporters
}  // namespace robottestingframework
