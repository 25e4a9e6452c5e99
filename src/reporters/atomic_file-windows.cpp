#include "reporters/atomic_file.h"

#include <windows.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace robottestingframework {
namespace reporters {

namespace {

// The system's words for a Win32 error code.
std::string systemMessage(DWORD code) {
    char buffer[512] = {};
    const DWORD length = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
                                        nullptr, code, 0, buffer, sizeof(buffer), nullptr);
    std::string text(buffer, length);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == '.')) {
        text.pop_back();
    }
    return text.empty() ? "error " + std::to_string(code) : text;
}

bool writeAll(HANDLE handle, const std::string& content, DWORD& code) {
    std::size_t done = 0;
    while (done < content.size()) {
        const std::size_t left = content.size() - done;
        const DWORD chunk = left > (1u << 30) ? (1u << 30) : static_cast<DWORD>(left);
        DWORD wrote = 0;
        if (WriteFile(handle, content.data() + done, chunk, &wrote, nullptr) == 0) {
            code = GetLastError();
            return false;
        }
        done += wrote;
    }
    return true;
}

// A device (NUL, CON, a named pipe) is written as it is, never replaced: the handle is open on
// it. Returns false with `error` when writing failed.
bool writeThrough(const std::string& filename, HANDLE handle, const std::string& content,
                  std::string& error) {
    DWORD code = 0;
    const bool written = writeAll(handle, content, code);
    CloseHandle(handle);
    if (!written) {
        error = "cannot write " + filename + ": " + systemMessage(code);
    }
    return written;
}

}  // namespace

std::string notAnOutputFile(const std::string& filename) {
    const DWORD attributes = GetFileAttributesA(filename.c_str());
    if (attributes == INVALID_FILE_ATTRIBUTES || (attributes & FILE_ATTRIBUTE_DIRECTORY) == 0) {
        return {};
    }
    return filename + " is a folder; an output is a file (or a device, written through)";
}

bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error) {
    const std::string refused = notAnOutputFile(filename);
    if (!refused.empty()) {
        error = "cannot write " + refused;
        return false;
    }
    // What is there already: a device is written through, a file replaced.
    HANDLE existing =
        CreateFileA(filename.c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
                    OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (existing != INVALID_HANDLE_VALUE) {
        if (GetFileType(existing) != FILE_TYPE_DISK) {
            return writeThrough(filename, existing, content, error);
        }
        CloseHandle(existing);
    }
    const std::string temporary =
        filename + ".tmp." + std::to_string(static_cast<unsigned long>(GetCurrentProcessId()));
    auto fail = [&](const std::string& what, DWORD code) {
        error = "cannot " + what + " " + filename + ": " + systemMessage(code);
        DeleteFileA(temporary.c_str());
        return false;
    };
    // The C library's fopen, as on POSIX: its errno gives the same words there and here
    // ("No such file or directory").
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr) {
        error = "cannot write " + filename + ": " + std::strerror(errno);
        return false;
    }
    const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
    const int writeErrno = errno;
    if (std::fclose(file) != 0 || !written) {
        error = "cannot write " + filename + ": " + std::strerror(written ? errno : writeErrno);
        std::remove(temporary.c_str());
        return false;
    }
    if (MoveFileExA(temporary.c_str(), filename.c_str(),
                    MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) == 0) {
        return fail("rename a temporary file to", GetLastError());
    }
    return true;
}

}  // namespace reporters
}  // namespace robottestingframework
