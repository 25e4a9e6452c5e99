#include "reporters/atomic_file.h"

#include <fcntl.h>
#include <io.h>
#include <sys/stat.h>
#include <windows.h>

#include <cerrno>
#include <cstring>

#include "platform/system_error.h"

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

// The C library's descriptors, as on POSIX: its errno gives the same words there and here
// ("No such file or directory").
bool AtomicFile::openFile(const std::string& filename, std::string& error) {
    const std::string refused = notAnOutputFile(filename);
    if (!refused.empty()) {
        error = "cannot write " + refused;
        return false;
    }
    if (!isDevice(filename)) {
        return openTemporary(filename, error);
    }
    fd_ = ::_open(filename.c_str(), _O_WRONLY | _O_BINARY | _O_NOINHERIT);
    if (fd_ < 0) {
        error = "cannot write " + filename + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

int AtomicFile::createFile(const std::string& path) {
    return ::_open(path.c_str(), _O_WRONLY | _O_CREAT | _O_TRUNC | _O_BINARY | _O_NOINHERIT,
                   _S_IREAD | _S_IWRITE);
}

long AtomicFile::writeSome(int fd, const char* data, std::size_t size) {
    const unsigned chunk = size > (1u << 30) ? (1u << 30) : static_cast<unsigned>(size);
    return ::_write(fd, data, chunk);
}

int AtomicFile::closeFile(int fd) {
    return ::_close(fd);
}

std::string AtomicFile::processId() {
    return std::to_string(static_cast<unsigned long>(GetCurrentProcessId()));
}

std::string AtomicFile::replaceFile(const std::string& temporary, const std::string& target) {
    if (MoveFileExA(temporary.c_str(), target.c_str(),
                    MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) == 0) {
        return platform::systemErrorText(GetLastError());
    }
    return {};
}

}  // namespace reporters
}  // namespace robottestingframework
