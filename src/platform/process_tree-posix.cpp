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

// pid -> parent pid of every process, from /proc/<pid>/stat (Linux).
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
        char path[64];
        std::snprintf(path, sizeof(path), "/proc/%ld/stat", pid);
        FILE* file = std::fopen(path, "re");
        if (file == nullptr) {
            continue;
        }
        char buffer[1024];
        size_t n = std::fread(buffer, 1, sizeof(buffer) - 1, file);
        std::fclose(file);
        buffer[n] = '\0';
        // "pid (comm) state ppid ...": comm may hold spaces and parentheses; take the last ')'.
        char* close = std::strrchr(buffer, ')');
        char state;
        long parent;
        if (close != nullptr && std::sscanf(close + 1, " %c %ld", &state, &parent) == 2 &&
            state != 'Z' && state != 'X') {
            children.emplace(static_cast<pid_t>(parent), static_cast<pid_t>(pid));
        }
    }
    ::closedir(proc);
    return children;
}

}  // namespace

bool signalProcessGroup(pid_t group, int signal) {
    return group > 1 && ::kill(-group, signal) == 0;
}

std::vector<pid_t> descendantsOf(pid_t root) {
    std::multimap<pid_t, pid_t> children = childrenByParent();
    std::vector<pid_t> found;
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
