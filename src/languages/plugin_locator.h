// Finds the file of a test or fixture and tells its type, as both executors need before they
// load anything: the same rules and the same error words whatever the isolation mode.
#pragma once

#include <string>

namespace robottestingframework {
namespace languages {

// `plugin` as written in the suite (path or bare name), `givenPath` when already resolved,
// `givenType` when the suite says it, `suiteFile` the file that named it (its folder is searched
// first). Fills `path` and `type`; false with `error` saying what was tried or expected.
bool locatePlugin(const std::string& plugin, const std::string& givenPath,
                  const std::string& givenType, const std::string& suiteFile, std::string& path,
                  std::string& type, std::string& error);

}  // namespace languages
}  // namespace robottestingframework
