#include "dll/rtf2_library.h"

#include "dll/needed_libraries.h"

namespace robottestingframework {
namespace plugin {

namespace {

// librobottestingframework[-dll|-lua|-python|-ruby].so.N with N below 3: RTF 2.x's (and 1.x's)
// file names. This framework's libraries are named otherwise (libRobotTestingFramework*.so.3),
// RTF 2.x's names being only links to them for linking.
bool isRtf2Library(const std::string& name) {
    static const std::string base = "librobottestingframework";
    static const char* const companions[] = {"", "-dll", "-lua", "-python", "-ruby"};
    for (const char* companion : companions) {
        const std::string prefix = base + companion + ".so.";
        if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0) {
            const char major = name[prefix.size()];
            const bool alone = name.size() == prefix.size() + 1 || name[prefix.size() + 1] == '.';
            return alone && major >= '0' && major <= '2';
        }
    }
    return false;
}

}  // namespace

std::string rtf2LibraryNeeded(const std::string& path) {
    for (const std::string& name : neededLibraries(path)) {
        if (isRtf2Library(name)) {
            return name;
        }
    }
    return {};
}

std::string builtAgainstRtf2(const std::string& path, const std::string& library) {
    return "'" + path + "' was built against RTF 2.x: it needs " + library +
           ", which Robot Testing Framework 3 never loads (both define the same classes). Its "
           "sources compile unchanged against "
           "this version: rebuild it (CMake: find_package(RobotTestingFramework) and link "
           "RobotTestingFramework::RTF and RobotTestingFramework::RTF_dll; a Makefile: "
           "-lrobottestingframework -lrobottestingframework-dll, with this version's "
           "include and library folders)";
}

}  // namespace plugin
}  // namespace robottestingframework
