// Waiting for files to change (the runner's --watch, docs/how-to/watch.md). Linux: inotify on the
// files' folders (an editor that saves by renaming a new file over the old one is seen too).
// Other POSIX systems (macOS, the portable build): the files' modification times and sizes
// polled twice a second. Windows: not supported, watch() says so.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace robottestingframework {
namespace platform {

class FileWatch {
public:
    FileWatch();
    ~FileWatch();
    FileWatch(const FileWatch&) = delete;
    FileWatch& operator=(const FileWatch&) = delete;

    // Watches `files` (replacing what was watched); false with `error` when this system cannot.
    bool watch(const std::vector<std::string>& files, std::string& error);

    // Waits at most `timeoutMs` for a watched file to be written, replaced, touched or
    // removed; true with its path in `changed` when one was.
    bool waitForChange(int timeoutMs, std::string& changed);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace platform
}  // namespace robottestingframework
