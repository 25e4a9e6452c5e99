// Windows: what the runner needs of process.h so far. Spawning and waiting for workers and exec
// tests are not built for Windows yet (README: Platforms).
#include "platform/process.h"

#include <windows.h>

namespace robottestingframework {
namespace platform {

bool becomeSubreaper() {
    // Windows never re-parents an orphan; its descendants are found by the parent ids they
    // were started with (process_tree-windows.cpp).
    return false;
}

std::string executablePath() {
    std::string path(MAX_PATH, '\0');
    for (;;) {
        DWORD n = ::GetModuleFileNameA(nullptr, &path[0], static_cast<DWORD>(path.size()));
        if (n == 0) {
            return {};
        }
        if (n < path.size()) {
            path.resize(n);
            return path;
        }
        path.resize(path.size() * 2);
    }
}

}  // namespace platform
}  // namespace robottestingframework
