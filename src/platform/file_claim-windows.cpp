#include "platform/file_claim.h"

#include <windows.h>

#include "platform/system_error.h"

namespace robottestingframework {
namespace platform {

namespace {

// The byte locked: past the end of any log, so the file's own bytes stay writable through the
// handles of the process that holds the claim.
constexpr DWORD kLockedHigh = 0x7fffffff;

}  // namespace

bool FileClaim::take(const std::string& path, bool& busy, std::string& error) {
    release();
    busy = false;
    HANDLE file = CreateFileA(path.c_str(), GENERIC_READ,
                              FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                              OPEN_ALWAYS, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (file == INVALID_HANDLE_VALUE) {
        error = systemErrorText(GetLastError());
        return false;
    }
    OVERLAPPED at{};
    at.OffsetHigh = kLockedHigh;
    if (LockFileEx(file, LOCKFILE_EXCLUSIVE_LOCK | LOCKFILE_FAIL_IMMEDIATELY, 0, 1, 0, &at) == 0) {
        const DWORD why = GetLastError();
        CloseHandle(file);
        if (why == ERROR_LOCK_VIOLATION || why == ERROR_IO_PENDING) {
            busy = true;
        } else {
            error = systemErrorText(why);
        }
        return false;
    }
    handle_ = reinterpret_cast<std::intptr_t>(file);
    return true;
}

void FileClaim::release() {
    if (handle_ != -1) {
        CloseHandle(reinterpret_cast<HANDLE>(handle_));  // lets the lock go
        handle_ = -1;
    }
}

}  // namespace platform
}  // namespace robottestingframework
