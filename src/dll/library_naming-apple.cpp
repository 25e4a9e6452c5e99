// macOS (dyld): lib*.dylib, found along DYLD_LIBRARY_PATH, then DYLD_FALLBACK_LIBRARY_PATH,
// whose default is $HOME/lib, /usr/local/lib and /usr/lib (dlopen(3) on macOS). Compiled only
// for Apple: on Linux, `./run.sh test` checks that it compiles (its syntax), not how it runs.
#include <cstdlib>
#include <sstream>

#include "dll/library_naming.h"

namespace robottestingframework {
namespace plugin {

const LibraryNaming kLibraryNaming{"lib", ".dylib", "DYLD_LIBRARY_PATH", ':', "/", false};

std::vector<std::string> systemLibraryFolders() {
    std::vector<std::string> folders;
    const char* fallback = std::getenv("DYLD_FALLBACK_LIBRARY_PATH");
    if (fallback != nullptr) {
        std::stringstream stream(fallback);
        std::string folder;
        while (std::getline(stream, folder, ':')) {
            if (!folder.empty()) {
                folders.push_back(folder);
            }
        }
        return folders;
    }
    if (const char* home = std::getenv("HOME")) {
        folders.push_back(std::string(home) + "/lib");
    }
    folders.push_back("/usr/local/lib");
    folders.push_back("/usr/lib");
    return folders;
}

}  // namespace plugin
}  // namespace robottestingframework
