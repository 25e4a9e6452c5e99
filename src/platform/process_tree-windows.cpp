// Windows: the process tree from a Toolhelp snapshot (each process's parent id). Windows keeps
// no tree: a process whose parent ended still names that parent's id, which a later process may
// have reused, so a process that started before its supposed parent is not its child.
#include "platform/process_tree.h"

#include <windows.h>
// After windows.h, which it needs.
#include <tlhelp32.h>

#include <map>

namespace robottestingframework {
namespace platform {

namespace {

struct ProcessEntry {
    DWORD parent = 0;
    ULONGLONG started = 0;  // FILETIME ticks; 0 when it cannot be told
};

ULONGLONG startTime(DWORD pid) {
    HANDLE process = ::OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, pid);
    if (process == nullptr) {
        return 0;
    }
    FILETIME created{}, exited{}, kernel{}, user{};
    ULONGLONG ticks = 0;
    if (::GetProcessTimes(process, &created, &exited, &kernel, &user)) {
        ticks = (static_cast<ULONGLONG>(created.dwHighDateTime) << 32) | created.dwLowDateTime;
    }
    ::CloseHandle(process);
    return ticks;
}

std::map<DWORD, ProcessEntry> snapshot() {
    std::map<DWORD, ProcessEntry> processes;
    HANDLE snap = ::CreateToolhelp32Snapshot(TH32CS_SNAPPROCESS, 0);
    if (snap == INVALID_HANDLE_VALUE) {
        return processes;
    }
    PROCESSENTRY32 entry{};
    entry.dwSize = sizeof(entry);
    for (BOOL more = ::Process32First(snap, &entry); more; more = ::Process32Next(snap, &entry)) {
        processes[entry.th32ProcessID].parent = entry.th32ParentProcessID;
    }
    ::CloseHandle(snap);
    for (auto& process : processes) {
        process.second.started = startTime(process.first);
    }
    return processes;
}

}  // namespace

std::vector<pid_t> descendantsOf(pid_t root) {
    const auto processes = snapshot();
    std::vector<pid_t> found;
    std::vector<DWORD> parents{static_cast<DWORD>(root)};
    for (std::size_t next = 0; next < parents.size(); ++next) {
        const DWORD parent = parents[next];
        const auto parentEntry = processes.find(parent);
        const ULONGLONG parentStarted =
            parentEntry != processes.end() ? parentEntry->second.started : 0;
        for (const auto& process : processes) {
            if (process.second.parent != parent || process.first == parent ||
                process.first == static_cast<DWORD>(root)) {
                continue;
            }
            if (parentStarted != 0 && process.second.started != 0 &&
                process.second.started < parentStarted) {
                continue;  // the parent id was reused
            }
            found.push_back(static_cast<pid_t>(process.first));
            parents.push_back(process.first);
        }
    }
    return found;
}

std::size_t killDescendants(pid_t root) {
    // No freezing on Windows: repeat until a snapshot finds none left (bounded).
    std::size_t killed = 0;
    for (int round = 0; round < 10; ++round) {
        const auto descendants = descendantsOf(root);
        if (descendants.empty()) {
            break;
        }
        for (pid_t pid : descendants) {
            HANDLE process =
                ::OpenProcess(PROCESS_TERMINATE | SYNCHRONIZE, FALSE, static_cast<DWORD>(pid));
            if (process == nullptr) {
                continue;
            }
            if (::TerminateProcess(process, 1)) {
                ::WaitForSingleObject(process, 1000);
                ++killed;
            }
            ::CloseHandle(process);
        }
    }
    return killed;
}

}  // namespace platform
}  // namespace robottestingframework
