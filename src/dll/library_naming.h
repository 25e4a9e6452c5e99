// How the system's dynamic loader names and finds libraries, one file per system:
// library_naming-linux.cpp (lib*.so, LD_LIBRARY_PATH, ld.so.conf), library_naming-apple.cpp
// (lib*.dylib, DYLD_LIBRARY_PATH, DYLD_FALLBACK_LIBRARY_PATH). SharedLibrary::prefix() and
// suffix() are defined there too.
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {
namespace plugin {

// The environment variable whose folders the loader searches first for a bare name.
const char* libraryPathVariable();
// What separates the folders of such a variable, and of RTF_PLUGIN_PATH: ':', on Windows ';'
// (a drive letter's colon is part of a path there).
char pathListSeparator();

// The folders it searches after those, in its order.
std::vector<std::string> systemLibraryFolders();

}  // namespace plugin
}  // namespace robottestingframework
