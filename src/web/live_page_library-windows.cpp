#include "web/live_page_library.h"

#include <windows.h>

#include <string>

namespace robottestingframework {
namespace web {

namespace {

// The folder this library (RTF) was loaded from: RTF_web is built beside it.
std::string ownFolder() {
    HMODULE self = nullptr;
    if (GetModuleHandleExA(
            GET_MODULE_HANDLE_EX_FLAG_FROM_ADDRESS | GET_MODULE_HANDLE_EX_FLAG_UNCHANGED_REFCOUNT,
            reinterpret_cast<LPCSTR>(&loadLivePageLibrary), &self) == 0) {
        return {};
    }
    char path[MAX_PATH] = {};
    const DWORD length = GetModuleFileNameA(self, path, MAX_PATH);
    if (length == 0 || length >= MAX_PATH) {
        return {};
    }
    const std::string file(path, length);
    const std::size_t slash = file.find_last_of("\\/");
    return slash == std::string::npos ? std::string() : file.substr(0, slash + 1);
}

}  // namespace

void* loadLivePageFile(std::string& error) {
    const std::string beside = ownFolder() + RTF_WEB_LIBRARY_FILE;
    HMODULE library = LoadLibraryA(beside.c_str());
    if (library == nullptr) {
        error = "cannot load the live page's library " + beside + " (error " +
                std::to_string(static_cast<unsigned long>(GetLastError())) + ")";
    }
    return reinterpret_cast<void*>(library);
}

void* livePageSymbol(void* library, const char* name) {
    return reinterpret_cast<void*>(GetProcAddress(reinterpret_cast<HMODULE>(library), name));
}

}  // namespace web
}  // namespace robottestingframework
