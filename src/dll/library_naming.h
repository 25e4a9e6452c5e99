// How the system's dynamic loader names and finds libraries, one file per system:
// library_naming-linux.cpp (lib*.so, LD_LIBRARY_PATH, ld.so.conf), library_naming-apple.cpp
// (lib*.dylib, DYLD_LIBRARY_PATH, DYLD_FALLBACK_LIBRARY_PATH), library_naming-windows.cpp
// (*.dll, PATH). What is only a name there is one row, kLibraryNaming, which
// library_naming.cpp reads for the functions below and SharedLibrary::prefix() and suffix().
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {
namespace plugin {

// How the system's loader names libraries and lists folders.
struct LibraryNaming {
    const char* prefix;            // of a library's file name: "lib"
    const char* suffix;            // ".so", ".dylib", ".dll"
    const char* pathVariable;      // see libraryPathVariable()
    char pathListSeparator;        // see pathListSeparator()
    const char* folderSeparators;  // what may end a folder's name: "/", on Windows "/\\"
    // The loader looks in the program's folder before the path variable (Windows): so does
    // SharedLibrary::searchPath() with the folder of RTF_dll.
    bool ownFolderFirst;
};
// This system's, in library_naming-<system>.cpp.
extern const LibraryNaming kLibraryNaming;

// The environment variable whose folders the loader searches first for a bare name.
const char* libraryPathVariable();
// What separates the folders of such a variable, and of RTF_PLUGIN_PATH: ':', on Windows ';'
// (a drive letter's colon is part of a path there).
char pathListSeparator();

// The folders it searches after those, in its order.
std::vector<std::string> systemLibraryFolders();

}  // namespace plugin
}  // namespace robottestingframework
