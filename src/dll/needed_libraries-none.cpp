#include "dll/needed_libraries.h"

namespace robottestingframework {
namespace plugin {

// Windows and macOS: the files are not read (PE imports and Mach-O load commands would be), so
// a plug-in built against RTF 2.x is not told apart before loading there
// (docs/development/platforms.md).
std::vector<std::string> neededLibraries(const std::string&) {
    return {};
}

}  // namespace plugin
}  // namespace robottestingframework
