// Linux (glibc's ld.so): lib*.so, found along LD_LIBRARY_PATH, then the folders of
// /etc/ld.so.conf (from which the loader's cache is built), then the multiarch and plain ones.
#include <glob.h>

#include <fstream>
#include <sstream>

#include "dll/library_naming.h"

namespace robottestingframework {
namespace plugin {

namespace {

// Folders listed in ld.so.conf (the loader's cache is built from them), following `include`.
void readLoaderConfig(const std::string& file, std::vector<std::string>& out, int depth) {
    std::ifstream in(file);
    std::string line;
    while (depth < 8 && std::getline(in, line)) {
        line = line.substr(0, line.find('#'));
        std::stringstream words(line);
        std::string word;
        if (!(words >> word)) {
            continue;
        }
        if (word == "include") {
            while (words >> word) {
                glob_t found{};
                if (::glob(word.c_str(), 0, nullptr, &found) == 0) {
                    for (std::size_t i = 0; i < found.gl_pathc; ++i) {
                        readLoaderConfig(found.gl_pathv[i], out, depth + 1);
                    }
                }
                ::globfree(&found);
            }
        } else if (word[0] == '/') {
            out.push_back(word);
        }
    }
}

}  // namespace

const LibraryNaming kLibraryNaming{"lib", ".so", "LD_LIBRARY_PATH", ':', "/", false};

std::vector<std::string> systemLibraryFolders() {
    std::vector<std::string> folders;
    readLoaderConfig("/etc/ld.so.conf", folders, 0);
#ifdef RTF_LIBRARY_ARCHITECTURE
    folders.push_back("/lib/" RTF_LIBRARY_ARCHITECTURE);
    folders.push_back("/usr/lib/" RTF_LIBRARY_ARCHITECTURE);
#endif
    folders.push_back("/lib");
    folders.push_back("/usr/lib");
    return folders;
}

}  // namespace plugin
}  // namespace robottestingframework
