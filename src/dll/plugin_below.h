// Where a plug-in that was not found lies below the working folder, for the message that says
// the option that would find it (`--plugin-path build/lib`): a first project's plug-in is built
// in its build tree, which nothing searches.
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {
namespace plugin {

// The first file named one of `names` below the working folder (itself included), shallowest
// first and in name order within a folder, as a relative path with '/' ("build/lib/libx.so");
// empty when there is none. Bounded: hidden folders (".git") and symbolic links to folders are
// not entered, at most 6 levels and 20 000 entries are looked at, so a home folder costs little.
std::string findBelowWorkingFolder(const std::vector<std::string>& names);

}  // namespace plugin
}  // namespace robottestingframework
