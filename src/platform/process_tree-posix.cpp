#include "platform/process_tree.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>

#include "platform/process.h"

namespace robottestingframework {
namespace platform {

namespace {

// The state and parent of `pid` from /proc/<pid>/stat; false when it is gone.
bool readStat(long pid, char& state, long& parent) {
    char path[64];
    std::snprintf(path, sizeof(path), "/proc/%ld/stat", pid);
    FILE* file = std::fopen(path, "re");
    if (file == nullptr) {
        return false;
    }
    char buffer[1024];
    size_t n = std::fread(buffer, 1, sizeof(buffer) - 1, file);
    std::fclose(file);
    buffer[n] = '\0';
    // "pid (comm) state ppid ...": comm may hold spaces and parentheses; take the last ')'.
    char* close = std::strrchr(buffer, ')');
    return close != nullptr && std::sscanf(close + 1, " %c %ld", &state, &parent) == 2;
}

bool living(char state) {
    return state != 'Z' && state != 'X';
}

// pid -> parent pid of every living process, from /proc/<pid>/stat: the fallback when the
// kernel has no /proc/<pid>/task/<tid>/children (CONFIG_PROC_CHILDREN).
std::multimap<pid_t, pid_t> childrenByParent() {
    std::multimap<pid_t, pid_t> children;
    DIR* proc = ::opendir("/proc");
    if (proc == nullptr) {
        return children;
    }
    while (dirent* entry = ::readdir(proc)) {
        char* end = nullptr;
        long pid = std::strtol(entry->d_name, &end, 10);
        if (pid <= 0 || *end != '\0') {
            continue;
        }
        char state;
        long parent;
        if (readStat(pid, state, parent) && living(state)) {
            children.emplace(static_cast<pid_t>(parent), static_cast<pid_t>(pid));
        }
    }
    ::closedir(proc);
    return children;
}

// Appends the children of `parent` (of each of its threads) listed by the kernel in
// /proc/<parent>/task/<tid>/children; false when this kernel does not list them. A process
// that ended meanwhile has no children: true, none added.
bool appendChildren(pid_t parent, std::vector<pid_t>& children) {
    char path[64];
    std::snprintf(path, sizeof(path), "/proc/%ld/task", static_cast<long>(parent));
    DIR* tasks = ::opendir(path);
    if (tasks == nullptr) {
        return true;
    }
    bool listed = true;
    while (dirent* entry = ::readdir(tasks)) {
        char* end = nullptr;
        long tid = std::strtol(entry->d_name, &end, 10);
        if (tid <= 0 || *end != '\0') {
            continue;
        }
        std::snprintf(path, sizeof(path), "/proc/%ld/task/%ld/children", static_cast<long>(parent),
                      tid);
        FILE* file = std::fopen(path, "re");
        if (file == nullptr) {
            // No such file for a thread that exists: the kernel does not list children.
            listed = listed && errno != ENOENT;
            continue;
        }
        long child;
        while (std::fscanf(file, "%ld", &child) == 1) {
            children.push_back(static_cast<pid_t>(child));
        }
        std::fclose(file);
    }
    ::closedir(tasks);
    return listed;
}

// Every living descendant of `root` through the kernel's lists of children: reads only the
// family's own files, not every process's (a one-test run used to read ~100 of them). False
// when the kernel has no such lists.
bool descendantsByChildLists(pid_t root, std::vector<pid_t>& found) {
    std::vector<pid_t> parents{root};
    while (!parents.empty()) {
        std::vector<pid_t> next;
        for (pid_t parent : parents) {
            std::vector<pid_t> children;
            if (!appendChildren(parent, children)) {
                return false;
            }
            for (pid_t child : children) {
                char state;
                long ignored;
                // A zombie is not living; its children, if any, went to a reaper already.
                if (readStat(child, state, ignored) && living(state)) {
                    found.push_back(child);
                    next.push_back(child);
                }
            }
        }
        parents.swap(next);
    }
    return true;
}

}  // namespace

bool signalProcessGroup(pid_t group, int signal) {
    return group > 1 && ::kill(-group, signal) == 0;
}

std::vector<pid_t> descendantsOf(pid_t root) {
    std::vector<pid_t> found;
    if (descendantsByChildLists(root, found)) {
        return found;
    }
    found.clear();
    std::multimap<pid_t, pid_t> children = childrenByParent();
    std::vector<pid_t> parents{root};
    while (!parents.empty()) {
        std::vector<pid_t> next;
        for (pid_t parent : parents) {
            auto range = children.equal_range(parent);
            for (auto it = range.first; it != range.second; ++it) {
                found.push_back(it->second);
                next.push_back(it->second);
            }
        }
        parents.swap(next);
    }
    return found;
}

std::size_t killDescendants(pid_t root) {
    std::set<pid_t> frozen;
    // A process may fork between our scan and its SIGSTOP; scan again until nothing is new.
    for (int round = 0; round < 50; ++round) {
        bool fresh = false;
        for (pid_t pid : descendantsOf(root)) {
            if (frozen.insert(pid).second) {
                ::kill(pid, SIGSTOP);
                fresh = true;
            }
        }
        if (!fresh) {
            break;
        }
    }
    for (pid_t pid : frozen) {
        ::kill(pid, SIGKILL);
    }
    return frozen.size();
}

int stopChildGroup(pid_t leader, double grace) {
    int status = 0;
    signalProcessGroup(leader, SIGTERM);
    // A stopped process does not act on SIGTERM until continued.
    signalProcessGroup(leader, SIGCONT);
    if (!waitChild(leader, grace, status)) {
        signalProcessGroup(leader, SIGKILL);
        waitChild(leader, -1, status);
    }
    // Whatever else is left in the group goes too.
    signalProcessGroup(leader, SIGKILL);
    return status;
}

}  // namespace platform
}  // namespace robottestingframework
