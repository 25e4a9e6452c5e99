#include "dll/shared_library.h"

#include <windows.h>

#include <cstdlib>

#include "platform/system_error.h"

namespace robottestingframework {
namespace plugin {

namespace {

// The system's words for the last error, and its code, as dlerror would give them on Linux.
std::string lastError(const std::string& what) {
    const DWORD code = GetLastError();
    return what + ": " + platform::systemErrorText(code) + " (error " + std::to_string(code) + ")";
}

std::string folderOf(const std::string& path) {
    const std::size_t slash = path.find_last_of("\\/");
    return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

}  // namespace

bool SharedLibrary::open(const std::string& path) {
    close();
    // LOAD_WITH_ALTERED_SEARCH_PATH: the DLLs a plug-in needs are looked for beside it first,
    // as its RPATH would make them on Linux. No dialog box for a missing DLL.
    const UINT previous = SetErrorMode(SEM_FAILCRITICALERRORS | SEM_NOOPENFILEERRORBOX);
    HMODULE module = LoadLibraryExA(path.c_str(), nullptr, LOAD_WITH_ALTERED_SEARCH_PATH);
    const DWORD code = GetLastError();
    SetErrorMode(previous);
    if (module == nullptr) {
        SetLastError(code);
        error_ = lastError(path);
        return false;
    }
    handle_ = reinterpret_cast<void*>(module);
    error_.clear();
    return true;
}

void SharedLibrary::close() {
    if (handle_ != nullptr) {
        FreeLibrary(reinterpret_cast<HMODULE>(handle_));
        handle_ = nullptr;
    }
}

void* SharedLibrary::symbol(const char* name) {
    if (handle_ == nullptr) {
        error_ = "the library is not open";
        return nullptr;
    }
    FARPROC address = GetProcAddress(reinterpret_cast<HMODULE>(handle_), name);
    if (address == nullptr) {
        error_ = lastError(std::string("no symbol ") + name);
        return nullptr;
    }
    return reinterpret_cast<void*>(address);
}

// The folder of this DLL (RTF_dll): the project's plug-ins are found beside it.
std::string SharedLibrary::ownFolder() {
    HMODULE self = nullptr;
    if (GetModuleHandleExA(
            GET_MODULE_HANDLE_EX_FLAG_FROM_ADDRESS | GET_MODULE_HANDLE_EX_FLAG_UNCHANGED_REFCOUNT,
            reinterpret_cast<LPCSTR>(&SharedLibrary::ownFolder), &self) == 0) {
        return {};
    }
    char path[MAX_PATH] = {};
    const DWORD length = GetModuleFileNameA(self, path, MAX_PATH);
    return length == 0 || length >= MAX_PATH ? std::string() : folderOf(std::string(path, length));
}

}  // namespace plugin
}  // namespace robottestingframework
