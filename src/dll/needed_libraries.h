// The libraries a shared library file names as its own dependencies (ELF's DT_NEEDED entries),
// read from the file without loading it: a plug-in that would bring a library which must never
// share a process with this framework (RTF 2.x's) is refused before the loader maps anything.
// One header; needed_libraries-elf.cpp reads ELF files with libelf, needed_libraries-none.cpp
// (Windows, macOS) reads nothing.
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {
namespace plugin {

// The names `path` needs, in its order; empty when the file cannot be read or is not of the
// platform's format (the loader's own error says so when it is opened).
std::vector<std::string> neededLibraries(const std::string& path);

}  // namespace plugin
}  // namespace robottestingframework
