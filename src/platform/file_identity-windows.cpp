// Windows: the volume serial number and file index of an open handle
// (GetFileInformationByHandle); a folder opens too (FILE_FLAG_BACKUP_SEMANTICS), and opening shares
// everything, so a file another program writes is still identified.
#include "platform/file_identity.h"

#include <windows.h>

#include <filesystem>

namespace robottestingframework {
namespace platform {

std::string fileIdentity(const std::string& path, bool* writtenThrough) {
    const std::wstring wide = std::filesystem::u8path(path).wstring();
    HANDLE file =
        ::CreateFileW(wide.c_str(), 0, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                      nullptr, OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
    if (file == INVALID_HANDLE_VALUE) {
        return {};
    }
    BY_HANDLE_FILE_INFORMATION info{};
    const bool known = ::GetFileInformationByHandle(file, &info) != 0;
    const DWORD type = ::GetFileType(file);
    ::CloseHandle(file);
    if (!known) {
        return {};
    }
    if (writtenThrough != nullptr) {
        *writtenThrough = type != FILE_TYPE_DISK;
    }
    const unsigned long long index =
        (static_cast<unsigned long long>(info.nFileIndexHigh) << 32) | info.nFileIndexLow;
    return std::to_string(info.dwVolumeSerialNumber) + ":" + std::to_string(index);
}

}  // namespace platform
}  // namespace robottestingframework
