#include "platform/file_watch.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

namespace robottestingframework {
namespace platform {

namespace fs = std::filesystem;

struct FileWatch::State {
    int fd = -1;
    // Each watched folder's descriptor, and the names watched in it.
    std::map<int, std::pair<std::string, std::set<std::string>>> folders;
};

FileWatch::FileWatch() : state_(new State) {}

FileWatch::~FileWatch() {
    if (state_->fd >= 0) {
        ::close(state_->fd);
    }
}

bool FileWatch::watch(const std::vector<std::string>& files, std::string& error) {
    if (state_->fd >= 0) {
        ::close(state_->fd);
    }
    state_->folders.clear();
    state_->fd = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (state_->fd < 0) {
        error = std::string("inotify: ") + std::strerror(errno);
        return false;
    }
    std::map<std::string, int> byFolder;
    for (const auto& file : files) {
        std::error_code failed;
        const fs::path path = fs::absolute(file, failed).lexically_normal();
        const std::string folder = path.parent_path().string();
        auto known = byFolder.find(folder);
        if (known == byFolder.end()) {
            const int wd = ::inotify_add_watch(
                state_->fd, folder.c_str(),
                IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_ATTRIB | IN_MODIFY);
            if (wd < 0) {
                continue;  // a folder that is gone: nothing of it to see
            }
            known = byFolder.emplace(folder, wd).first;
            state_->folders[wd].first = folder;
        }
        state_->folders[known->second].second.insert(path.filename().string());
    }
    return true;
}

bool FileWatch::waitForChange(int timeoutMs, std::string& changed) {
    if (state_->fd < 0) {
        ::usleep(static_cast<useconds_t>(timeoutMs) * 1000);
        return false;
    }
    pollfd ready{state_->fd, POLLIN, 0};
    if (::poll(&ready, 1, timeoutMs) <= 0) {
        return false;
    }
    alignas(inotify_event) char buffer[16384];
    bool found = false;
    for (;;) {
        const ssize_t got = ::read(state_->fd, buffer, sizeof buffer);
        if (got <= 0) {
            break;
        }
        for (ssize_t at = 0; at < got;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            auto folder = state_->folders.find(event->wd);
            if (folder == state_->folders.end() || event->len == 0) {
                continue;
            }
            const std::string name = event->name;
            if (!found && folder->second.second.count(name) > 0) {
                changed = folder->second.first + "/" + name;
                found = true;
            }
        }
    }
    return found;
}

}  // namespace platform
}  // namespace robottestingframework
