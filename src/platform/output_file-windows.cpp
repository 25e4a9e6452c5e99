// Windows: a temporary file that Windows deletes when the last handle on it closes (there is no
// unlinking an open file), under C run-time descriptors.
#include "platform/output_file.h"

#include <fcntl.h>
#include <io.h>
#include <stdio.h>
#include <windows.h>

namespace robottestingframework {
namespace platform {

FileDescriptor makeOutputFile(std::string& error) {
    char folder[MAX_PATH + 1] = {};
    if (::GetTempPathA(sizeof(folder), folder) == 0) {
        error = "cannot tell the temporary folder";
        return {};
    }
    char name[MAX_PATH + 1] = {};
    if (::GetTempFileNameA(folder, "rtf", 0, name) == 0) {
        error = std::string("cannot create a file to capture the tests' output in ") + folder;
        return {};
    }
    HANDLE file = ::CreateFileA(
        name, GENERIC_READ | GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
        nullptr, CREATE_ALWAYS, FILE_ATTRIBUTE_TEMPORARY | FILE_FLAG_DELETE_ON_CLOSE, nullptr);
    if (file == INVALID_HANDLE_VALUE) {
        error = std::string("cannot open ") + name + " to capture the tests' output";
        ::DeleteFileA(name);
        return {};
    }
    // Append mode: after emptyOutputFile, writes start again at the file's beginning.
    FileDescriptor fd(::_open_osfhandle(reinterpret_cast<intptr_t>(file), _O_APPEND | _O_BINARY));
    if (!fd.valid()) {
        ::CloseHandle(file);
        error = "cannot open a descriptor on the capture file";
    }
    return fd;
}

int copyDescriptor(int fd) {
    const int copy = ::_dup(fd);
    if (copy >= 0) {
        setCloseOnExec(copy);
    }
    return copy;
}

bool pointDescriptor(int fd, int target) {
    return ::_dup2(fd, target) == 0;
}

void closeDescriptor(int fd) {
    ::_close(fd);
}

std::FILE* writeStreamOn(int fd) {
    return ::_fdopen(fd, "w");
}

long long outputFileSize(int fd) {
    return ::_lseeki64(fd, 0, SEEK_END);
}

std::size_t readOutputFile(int fd, long long offset, char* data, std::size_t size) {
    if (::_lseeki64(fd, offset, SEEK_SET) < 0) {
        return 0;
    }
    std::size_t done = 0;
    while (done < size) {
        int n = ::_read(fd, data + done, static_cast<unsigned int>(size - done));
        if (n <= 0) {
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    return done;
}

bool emptyOutputFile(int fd) {
    return ::_chsize_s(fd, 0) == 0;
}

}  // namespace platform
}  // namespace robottestingframework
