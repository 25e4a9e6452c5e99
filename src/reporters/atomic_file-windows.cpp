#include "reporters/atomic_file.h"

#include <fcntl.h>
#include <io.h>
#include <sys/stat.h>
#include <windows.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "platform/system_error.h"
#include "reporters/standard_output.h"

namespace robottestingframework {
namespace reporters {

namespace {

// A device (NUL, CON, a named pipe) that is already there: written as it is, never replaced.
bool isDevice(const std::string& filename) {
    HANDLE existing =
        CreateFileA(filename.c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
                    OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (existing == INVALID_HANDLE_VALUE) {
        return false;
    }
    const bool device = GetFileType(existing) != FILE_TYPE_DISK;
    CloseHandle(existing);
    return device;
}

}  // namespace

std::string notAnOutputFile(const std::string& filename) {
    const DWORD attributes = GetFileAttributesA(filename.c_str());
    if (attributes == INVALID_FILE_ATTRIBUTES || (attributes & FILE_ATTRIBUTE_DIRECTORY) == 0) {
        return {};
    }
    return filename + " is a folder; an output is a file (or a device, written through)";
}

AtomicFile::~AtomicFile() {
    discard();
}

void AtomicFile::discard() {
    if (fd_ >= 0) {
        ::_close(fd_);
        fd_ = -1;
    }
    if (!temporary_.empty()) {
        std::remove(temporary_.c_str());
        temporary_.clear();
    }
}

// The C library's descriptors, as on POSIX: its errno gives the same words there and here
// ("No such file or directory").
bool AtomicFile::open(const std::string& filename, std::string& error) {
    discard();
    filename_ = filename;
    writeErrno_ = 0;
    if (namesStandardOutput(filename)) {
        fd_ = openStandardOutput();  // "-": the standard output, written through
        if (fd_ < 0) {
            error = "cannot write " + filename + ": " + std::strerror(errno);
            return false;
        }
        return true;
    }
    const std::string refused = notAnOutputFile(filename);
    if (!refused.empty()) {
        error = "cannot write " + refused;
        return false;
    }
    if (isDevice(filename)) {
        fd_ = ::_open(filename.c_str(), _O_WRONLY | _O_BINARY | _O_NOINHERIT);
        if (fd_ < 0) {
            error = "cannot write " + filename + ": " + std::strerror(errno);
            return false;
        }
        return true;
    }
    target_ = filename;
    temporary_ =
        filename + ".tmp." + std::to_string(static_cast<unsigned long>(GetCurrentProcessId()));
    fd_ = ::_open(temporary_.c_str(), _O_WRONLY | _O_CREAT | _O_TRUNC | _O_BINARY | _O_NOINHERIT,
                  _S_IREAD | _S_IWRITE);
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
        const std::size_t left = size - done;
        const unsigned chunk = left > (1u << 30) ? (1u << 30) : static_cast<unsigned>(left);
        const int wrote = ::_write(fd_, data + done, chunk);
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
    if (::_close(fd) != 0 && code == 0) {
        code = errno;
    }
    if (code != 0) {
        error = "cannot write " + filename_ + ": " + std::strerror(code);
        discard();
        return false;
    }
    if (!temporary_.empty() &&
        MoveFileExA(temporary_.c_str(), target_.c_str(),
                    MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) == 0) {
        error = "cannot rename a temporary file to " + filename_ + ": " +
                platform::systemErrorText(GetLastError());
        discard();
        return false;
    }
    temporary_.clear();
    return true;
}

}  // namespace reporters
}  // namespace robottestingframework
