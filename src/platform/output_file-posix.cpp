#include "platform/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace robottestingframework {
namespace platform {

FileDescriptor makeOutputFile(std::string& error) {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") +
                          "/robottestingframework-output-XXXXXX";
    FileDescriptor file(::mkstemp(&pattern[0]));
    if (!file.valid()) {
        error = "cannot create a file to capture the tests' output in " + pattern + ": " +
                std::strerror(errno);
        return file;
    }
    ::unlink(pattern.c_str());
    // Append mode: after emptyOutputFile, writes start again at the file's beginning.
    ::fcntl(file.get(), F_SETFL, ::fcntl(file.get(), F_GETFL) | O_APPEND);
    setCloseOnExec(file.get());
    return file;
}

int copyDescriptor(int fd) {
    return ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
}

bool pointDescriptor(int fd, int target) {
    return ::dup2(fd, target) >= 0;
}

void closeDescriptor(int fd) {
    ::close(fd);
}

std::FILE* writeStreamOn(int fd) {
    return ::fdopen(fd, "w");
}

long long outputFileSize(int fd) {
    // Only appended to, so its end is its size: cheaper than fstat (it is asked twice per test).
    return ::lseek(fd, 0, SEEK_END);
}

std::size_t readOutputFile(int fd, long long offset, char* data, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        ssize_t n = ::pread(fd, data + done, size - done, static_cast<off_t>(offset + done));
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    return done;
}

bool emptyOutputFile(int fd) {
    return ::ftruncate(fd, 0) == 0;
}

}  // namespace platform
}  // namespace robottestingframework
