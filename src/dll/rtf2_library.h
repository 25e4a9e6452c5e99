// RTF 2.x's own libraries (librobottestingframework.so.2 and its -dll, -lua, -python, -ruby
// companions): a plug-in built against them cannot run with this framework (the two define
// the same classes), so it is refused, before loading, with a message that says how to rebuild
// it; its sources compile unchanged against this version.
#pragma once

#include <string>

namespace robottestingframework {
namespace plugin {

// The RTF 2.x library that the shared library `path` needs, or empty.
std::string rtf2LibraryNeeded(const std::string& path);

// What to tell the user of the plug-in `path` that needs `library` (an RTF 2.x library).
std::string builtAgainstRtf2(const std::string& path, const std::string& library);

}  // namespace plugin
}  // namespace robottestingframework
