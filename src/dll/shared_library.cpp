#include "dll/shared_library.h"

#include <cstdlib>
#include <set>
#include <sstream>

#include "dll/library_naming.h"

// What every platform shares; opening, closing and finding a symbol are in
// shared_library-<platform>.cpp.
namespace robottestingframework {
namespace plugin {

namespace {

void splitInto(const std::string& text, char separator, std::vector<std::string>& out) {
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, separator)) {
        if (!item.empty()) {
            out.push_back(item);
        }
    }
}

}  // namespace

SharedLibrary::~SharedLibrary() {
    close();
}

std::vector<std::string> SharedLibrary::searchPath() {
    std::vector<std::string> folders;
    const std::string own = ownFolder();
    if (kLibraryNaming.ownFolderFirst && !own.empty()) {
        folders.push_back(own);
    }
    if (const char* env = std::getenv(libraryPathVariable())) {
        splitInto(env, pathListSeparator(), folders);
    }
    if (!kLibraryNaming.ownFolderFirst && !own.empty()) {
        folders.push_back(own);
    }
    for (const std::string& folder : systemLibraryFolders()) {
        folders.push_back(folder);
    }

    // Each folder once, first place kept.
    const std::string separators = kLibraryNaming.folderSeparators;
    std::vector<std::string> unique;
    std::set<std::string> seen;
    for (auto& folder : folders) {
        while (folder.size() > 1 && separators.find(folder.back()) != std::string::npos) {
            folder.pop_back();
        }
        if (seen.insert(folder).second) {
            unique.push_back(folder);
        }
    }
    return unique;
}

}  // namespace plugin
}  // namespace robottestingframework
