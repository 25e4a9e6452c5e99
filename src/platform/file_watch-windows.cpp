#include "platform/file_watch.h"

namespace robottestingframework {
namespace platform {

struct FileWatch::State {};

FileWatch::FileWatch() : state_(new State) {}

FileWatch::~FileWatch() = default;

bool FileWatch::watch(const std::vector<std::string>& /*files*/, std::string& error) {
    error =
        "--watch is not supported on Windows yet (Linux watches with inotify, other POSIX "
        "systems poll); run the runner again by hand";
    return false;
}

bool FileWatch::waitForChange(int /*timeoutMs*/, std::string& /*changed*/) {
    return false;
}

}  // namespace platform
}  // namespace robottestingframework
