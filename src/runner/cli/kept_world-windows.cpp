// Windows: no world keeper (it needs AF_UNIX control sockets, SCM_RIGHTS and sessions);
// robottestingframework_discover_tests keeps one world per test there.
#include "runner/cli/kept_world.h"

namespace robottestingframework {
namespace runner {

bool joinKeptWorld(const std::string&, const std::string&, KeptWorld&, std::string& error) {
    error = "--world is not supported on Windows (no world keeper: one world per test)";
    return false;
}

}  // namespace runner
}  // namespace robottestingframework
