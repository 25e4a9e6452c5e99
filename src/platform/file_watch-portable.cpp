#include "platform/file_watch.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <thread>
#include <utility>

namespace robottestingframework {
namespace platform {

namespace fs = std::filesystem;

namespace {

// What a poll compares: the time of the last write and the size; both 0 when gone.
std::pair<fs::file_time_type, std::uintmax_t> stamp(const std::string& file) {
    std::error_code failed;
    const auto time = fs::last_write_time(file, failed);
    if (failed) {
        return {};
    }
    const auto size = fs::file_size(file, failed);
    return {time, failed ? 0 : size};
}

}  // namespace

struct FileWatch::State {
    std::vector<std::pair<std::string, std::pair<fs::file_time_type, std::uintmax_t>>> files;
};

FileWatch::FileWatch() : state_(new State) {}

FileWatch::~FileWatch() = default;

bool FileWatch::watch(const std::vector<std::string>& files, std::string& /*error*/) {
    state_->files.clear();
    for (const auto& file : files) {
        state_->files.emplace_back(file, stamp(file));
    }
    return true;
}

bool FileWatch::waitForChange(int timeoutMs, std::string& changed) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    for (;;) {
        for (auto& file : state_->files) {
            const auto now = stamp(file.first);
            if (now != file.second) {
                file.second = now;
                changed = file.first;
                return true;
            }
        }
        if (std::chrono::steady_clock::now() >= end) {
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
}

}  // namespace platform
}  // namespace robottestingframework
