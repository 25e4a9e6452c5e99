// Windows: C run-time descriptors over anonymous pipes. Such pipes cannot be waited on with a
// timeout (no poll, and WaitForMultipleObjects does not work on them), so waiting is bounded
// polling with PeekNamedPipe, and "non-blocking" is a property this file keeps per descriptor.
// Sockets and descriptor passing are POSIX-only (the fork server); they are not defined here.
#include "platform/file_descriptor.h"

#include <errno.h>
#include <fcntl.h>
#include <io.h>
#include <windows.h>

#include <algorithm>
#include <mutex>
#include <set>

#include "platform/clock.h"

namespace robottestingframework {
namespace platform {

namespace {

std::mutex nonBlockingMutex;
std::set<int>& nonBlockingFds() {
    static std::set<int> fds;
    return fds;
}

bool isNonBlocking(int fd) {
    std::lock_guard<std::mutex> lock(nonBlockingMutex);
    return nonBlockingFds().count(fd) > 0;
}

enum class PipeState { Data, Empty, Closed, NotAPipe };

PipeState pipeState(int fd) {
    HANDLE handle = reinterpret_cast<HANDLE>(::_get_osfhandle(fd));
    if (handle == INVALID_HANDLE_VALUE) {
        return PipeState::Closed;
    }
    DWORD available = 0;
    if (!::PeekNamedPipe(handle, nullptr, 0, nullptr, &available, nullptr)) {
        return ::GetLastError() == ERROR_BROKEN_PIPE ? PipeState::Closed : PipeState::NotAPipe;
    }
    return available > 0 ? PipeState::Data : PipeState::Empty;
}

}  // namespace

void FileDescriptor::reset(int fd) {
    if (fd_ >= 0) {
        setNonBlocking(fd_, false);  // the number may be reused for a blocking descriptor
        ::_close(fd_);
    }
    fd_ = fd;
}

bool makePipe(FileDescriptor& readEnd, FileDescriptor& writeEnd) {
    int fds[2];
    // Not inherited: the counterpart of close-on-exec.
    if (::_pipe(fds, 65536, _O_BINARY | _O_NOINHERIT) != 0) {
        return false;
    }
    readEnd.reset(fds[0]);
    writeEnd.reset(fds[1]);
    return true;
}

void setNonBlocking(int fd, bool on) {
    std::lock_guard<std::mutex> lock(nonBlockingMutex);
    if (on) {
        nonBlockingFds().insert(fd);
    } else {
        nonBlockingFds().erase(fd);
    }
}

void setCloseOnExec(int fd, bool on) {
    HANDLE handle = reinterpret_cast<HANDLE>(::_get_osfhandle(fd));
    if (handle != INVALID_HANDLE_VALUE) {
        ::SetHandleInformation(handle, HANDLE_FLAG_INHERIT, on ? 0 : HANDLE_FLAG_INHERIT);
    }
}

bool writeAll(int fd, const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const unsigned int chunk = static_cast<unsigned int>(std::min<std::size_t>(size, 1 << 20));
        int n = ::_write(fd, p, chunk);
        if (n <= 0) {
            return false;
        }
        p += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

long readSome(int fd, std::string& out, std::size_t max) {
    if (isNonBlocking(fd)) {
        PipeState state = pipeState(fd);
        if (state == PipeState::Empty) {
            errno = EAGAIN;
            return -1;
        }
        if (state == PipeState::Closed) {
            return 0;
        }
    }
    const std::size_t start = out.size();
    out.resize(start + max);
    int n = ::_read(fd, &out[start], static_cast<unsigned int>(max));
    out.resize(start + (n > 0 ? static_cast<std::size_t>(n) : 0));
    if (n < 0 && errno == EPIPE) {
        return 0;  // the writer is gone: end of file
    }
    return n;
}

bool waitReadable(const std::vector<int>& fds, int timeoutMs, std::vector<bool>& ready) {
    Deadline deadline(timeoutMs < 0 ? 0 : timeoutMs / 1000.0);
    for (;;) {
        ready.assign(fds.size(), false);
        bool any = false;
        for (std::size_t i = 0; i < fds.size(); ++i) {
            if (fds[i] >= 0 && pipeState(fds[i]) != PipeState::Empty) {
                ready[i] = true;  // data, end of file, or a file (always readable)
                any = true;
            }
        }
        if (any) {
            return true;
        }
        if (timeoutMs == 0 || (timeoutMs > 0 && deadline.expired())) {
            return false;
        }
        // 5 ms: well under what a person notices, and a few wake-ups a second when idle.
        ::Sleep(static_cast<DWORD>(timeoutMs < 0 ? 5 : std::min(5, deadline.remainingMs())));
    }
}

}  // namespace platform
}  // namespace robottestingframework
