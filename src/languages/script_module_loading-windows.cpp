// Windows: the script language modules are DLLs (robottestingframework-lua.dll), found and
// loaded with LoadLibrary as script_module_loading-posix.cpp does with dlopen. Only Lua is
// built (its source is Debian's, compiled by MinGW-w64); Python and Ruby need a Windows
// CPython or Ruby to link and test with, which these machines do not have
// (docs/development/platforms.md).
#include "languages/script_module_loading.h"

#include <windows.h>

#include <cstdlib>
#include <vector>

#include "platform/process.h"
#include "platform/system_error.h"

#ifndef RTF_LANGUAGE_RELATIVE_DIR
#define RTF_LANGUAGE_RELATIVE_DIR "../lib/robottestingframework"
#endif

namespace robottestingframework {
namespace languages {

namespace {

// LoadLibrary wants backslashes.
std::string windowsPath(std::string path) {
    for (char& c : path) {
        if (c == '/') {
            c = '\\';
        }
    }
    return path;
}

std::string folderOf(const std::string& path) {
    const std::size_t slash = path.find_last_of("\\/");
    return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

// The DLL this code is linked into (RobotTestingFrameworkLua.dll, see PluginLoader.h), or
// empty when it is linked into the program itself.
std::string libraryFile() {
    HMODULE self = nullptr;
    if (GetModuleHandleExA(
            GET_MODULE_HANDLE_EX_FLAG_FROM_ADDRESS | GET_MODULE_HANDLE_EX_FLAG_UNCHANGED_REFCOUNT,
            reinterpret_cast<LPCSTR>(&libraryFile), &self) == 0 ||
        self == GetModuleHandleA(nullptr)) {
        return {};
    }
    char path[MAX_PATH] = {};
    const DWORD length = GetModuleFileNameA(self, path, MAX_PATH);
    return length == 0 || length >= MAX_PATH ? std::string() : std::string(path, length);
}

// $RTF_LANGUAGE_DIR when set; else ..\lib\robottestingframework from the plug-in loader DLL
// and from the program (DLLs and programs both live in bin\ on Windows).
std::vector<std::string> moduleFolders() {
    if (const char* override = std::getenv("RTF_LANGUAGE_DIR")) {
        if (*override != '\0') {
            return {override};
        }
    }
    std::vector<std::string> folders;
    const std::string library = libraryFile();
    if (!library.empty()) {
        folders.push_back(folderOf(library) + "/" + RTF_LANGUAGE_RELATIVE_DIR);
    }
    const std::string self = platform::executablePath();
    if (!self.empty()) {
        folders.push_back(folderOf(self) + "/" + RTF_LANGUAGE_RELATIVE_DIR);
    }
    return folders;
}

// The system's words for the last error, as dlerror gives them on Linux.
std::string lastError(const std::string& what) {
    const DWORD code = GetLastError();
    return what + ": " + platform::systemErrorText(code) + " (error " + std::to_string(code) + ")";
}

}  // namespace

const LanguageModule* loadLanguageModule(const std::string& language, std::string& error) {
    const std::string file = "robottestingframework-" + language + ".dll";
    const std::vector<std::string> folders = moduleFolders();
    // The first folder that has the file; when none has it, the first one, so that the error
    // says which file is missing.
    std::string path = windowsPath(folders.empty() ? file : folders.front() + "/" + file);
    for (const std::string& folder : folders) {
        const std::string candidate = windowsPath(folder + "/" + file);
        if (GetFileAttributesA(candidate.c_str()) != INVALID_FILE_ATTRIBUTES) {
            path = candidate;
            break;
        }
    }
    // Its dependencies (RobotTestingFramework.dll, MinGW's run-time) are the program's own,
    // already loaded from bin\.
    HMODULE handle = LoadLibraryA(path.c_str());
    if (handle == nullptr) {
        error = lastError(path);
        return nullptr;
    }
    using Entry = const LanguageModule* (*)();
    FARPROC symbol = GetProcAddress(handle, RTF_LANGUAGE_MODULE_ENTRY);
    if (symbol == nullptr) {
        error = path + ": no " RTF_LANGUAGE_MODULE_ENTRY;
        FreeLibrary(handle);
        return nullptr;
    }
    const LanguageModule* module = reinterpret_cast<Entry>(reinterpret_cast<void*>(symbol))();
    if (module == nullptr || module->version != kLanguageModuleVersion ||
        module->loadTest == nullptr) {
        error = path + ": built for another version of the framework";
        FreeLibrary(handle);
        return nullptr;
    }
    return module;  // never freed: its objects live until the process ends
}

std::string unsupportedTypeReason(const std::string& type) {
    if (type == "python" || type == "ruby") {
        return std::string(type == "python" ? "Python" : "Ruby") +
               " tests are not built for Windows (no Windows " +
               (type == "python" ? "CPython" : "Ruby") + " to build them with)";
    }
    return type + " tests are not built for Windows yet";
}

}  // namespace languages
}  // namespace robottestingframework
