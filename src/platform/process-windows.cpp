// Windows: what the runner needs of process.h. Children start in job objects instead
// (job_process.h); a "wait status" here is a process's exit code.
#include "platform/process.h"

#include <windows.h>

#include "platform/signal_name.h"

namespace robottestingframework {
namespace platform {

bool becomeSubreaper() {
    // Windows never re-parents an orphan; its descendants are found by the parent ids they
    // were started with (process_tree-windows.cpp).
    return false;
}

ExitStatus ExitStatus::fromWaitStatus(int status) {
    ExitStatus result;
    const unsigned long code = static_cast<unsigned long>(status);
    // Exception codes are NTSTATUS errors (0xC...) or warnings (0x8...): a crash, reported as
    // POSIX reports a signal. Exit codes a program chooses are small.
    if ((code & 0xC0000000UL) == 0xC0000000UL || code == 0x80000003UL) {
        result.signaled = true;
        result.signal = status;
    } else {
        result.code = status;
    }
    return result;
}

std::string ExitStatus::toString() const {
    if (signaled) {
        return "crashed with " + signalName(signal) + " (" + signalDescription(signal) + ")";
    }
    return "exited with status " + std::to_string(code);
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

std::vector<std::string> shellCommand(const std::string& text) {
    return {"cmd.exe", "/d", "/s", "/c", text};
}

}  // namespace platform
}  // namespace robottestingframework
