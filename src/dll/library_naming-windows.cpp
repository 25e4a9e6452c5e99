// Windows: DLLs, named lib*.dll by MinGW and *.dll by MSVC (find_plugin tries both), found
// along PATH after the system's folders (the loader's order for a bare name, without the
// program's folder, which searchPath() puts first as the folder of RTF_dll).
#include <windows.h>

#include "dll/library_naming.h"

namespace robottestingframework {
namespace plugin {

const LibraryNaming kLibraryNaming{"lib", ".dll", "PATH", ';', "/\\", true};

std::vector<std::string> systemLibraryFolders() {
    std::vector<std::string> folders;
    char folder[MAX_PATH] = {};
    UINT length = GetSystemDirectoryA(folder, MAX_PATH);
    if (length > 0 && length < MAX_PATH) {
        folders.emplace_back(folder, length);
    }
    length = GetWindowsDirectoryA(folder, MAX_PATH);
    if (length > 0 && length < MAX_PATH) {
        folders.emplace_back(folder, length);
    }
    return folders;
}

}  // namespace plugin
}  // namespace robottestingframework
