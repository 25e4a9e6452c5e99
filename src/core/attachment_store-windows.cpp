#include "attachment_rules.h"
#include "attachment_store.h"

#include <windows.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>

#include "platform/system_error.h"

// The Windows twin of attachment_store-posix.cpp: the same rules (limits, names, one writer at
// a time through the folder's .lock), with Win32 handles and LockFileEx for open and flock.
namespace fs = std::filesystem;

namespace robottestingframework {

namespace {

class Handle {
public:
    explicit Handle(HANDLE handle) : handle_(handle) {}
    ~Handle() {
        if (valid()) {
            CloseHandle(handle_);
        }
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    bool valid() const { return handle_ != INVALID_HANDLE_VALUE && handle_ != nullptr; }
    HANDLE get() const { return handle_; }

private:
    HANDLE handle_;
};

bool copyBytes(HANDLE from, HANDLE to, std::uint64_t size, std::string& error) {
    char buffer[64 * 1024];
    std::uint64_t left = size;
    while (left > 0) {
        DWORD got = 0;
        const DWORD want = left < sizeof(buffer) ? static_cast<DWORD>(left) : sizeof(buffer);
        if (ReadFile(from, buffer, want, &got, nullptr) == 0) {
            error = platform::systemErrorText(GetLastError());
            return false;
        }
        if (got == 0) {
            break;  // the file shrank while copied: keep what there was
        }
        for (DWORD done = 0; done < got;) {
            DWORD put = 0;
            if (WriteFile(to, buffer + done, got - done, &put, nullptr) == 0) {
                error = platform::systemErrorText(GetLastError());
                return false;
            }
            done += put;
        }
        left -= got;
    }
    return true;
}

}  // namespace

bool storeCopy(AttachmentSteps& steps, const std::string& description, Attachment& attachment) {
    const std::string& source = steps.source();
    const DWORD attributes = GetFileAttributesA(source.c_str());
    if (attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_DIRECTORY) != 0) {
        return steps.fail("not a regular file");
    }
    Handle input(CreateFileA(source.c_str(), GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE,
                             nullptr, OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr));
    LARGE_INTEGER fileSize{};
    if (!input.valid() || GetFileSizeEx(input.get(), &fileSize) == 0) {
        return steps.fail(platform::systemErrorText(GetLastError()));
    }
    if (GetFileType(input.get()) != FILE_TYPE_DISK) {
        return steps.fail("not a regular file");
    }
    const auto size = static_cast<std::uint64_t>(fileSize.QuadPart);
    if (!steps.admitFile(size)) {
        return false;
    }
    // One writer at a time across the run's processes: the folder's content is the account.
    const std::string lockName = (steps.folder() / ".lock").string();
    Handle lock(CreateFileA(lockName.c_str(), GENERIC_READ | GENERIC_WRITE,
                            FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                            OPEN_ALWAYS, FILE_ATTRIBUTE_NORMAL, nullptr));
    OVERLAPPED whole{};
    if (!lock.valid() ||
        LockFileEx(lock.get(), LOCKFILE_EXCLUSIVE_LOCK, 0, MAXDWORD, MAXDWORD, &whole) == 0) {
        return steps.fail("cannot lock " + lockName + ": " +
                          platform::systemErrorText(GetLastError()));
    }
    if (!steps.admitRun(size)) {
        return false;
    }
    HANDLE output = INVALID_HANDLE_VALUE;
    while (output == INVALID_HANDLE_VALUE) {
        const std::string stored = steps.nextStored().string();
        output = CreateFileA(stored.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW,
                             FILE_ATTRIBUTE_NORMAL, nullptr);
        if (output == INVALID_HANDLE_VALUE && GetLastError() != ERROR_FILE_EXISTS) {
            return steps.fail("cannot write " + stored + ": " +
                              platform::systemErrorText(GetLastError()));
        }
    }
    std::string copyError;
    bool copied = false;
    {
        Handle outputFile(output);
        copied = copyBytes(input.get(), outputFile.get(), size, copyError);
    }
    if (!copied) {
        steps.discardStored();
        return steps.fail(copyError);
    }
    steps.describe(description, size, attachment);
    return true;
}

}  // namespace robottestingframework
