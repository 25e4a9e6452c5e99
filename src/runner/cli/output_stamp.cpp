#include "runner/cli/output_stamp.h"

#include <chrono>
#include <ctime>
#include <filesystem>

#include "platform/file_identity.h"

namespace fs = std::filesystem;

namespace robottestingframework {
namespace runner {

namespace {

// The local time of the file's last change, HH:MM:SS ("" when unknown).
std::string changedAt(const std::string& path) {
    std::error_code failed;
    const auto written = fs::last_write_time(path, failed);
    if (failed) {
        return {};
    }
    const auto now = std::chrono::system_clock::now() +
                     std::chrono::duration_cast<std::chrono::system_clock::duration>(
                         written - fs::file_time_type::clock::now());
    const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
    std::tm local{};
    localtime_r(&seconds, &local);  // as the JUnit report's timestamps
    char text[16];
    return std::strftime(text, sizeof text, "%H:%M:%S", &local) != 0 ? text : "";
}

}  // namespace

std::string outputStamp(const std::string& path) {
    bool writtenThrough = false;
    const std::string identity = platform::fileIdentity(path, &writtenThrough);
    if (identity.empty() || writtenThrough) {
        return {};
    }
    std::error_code failed;
    const auto size = fs::file_size(path, failed);
    const auto written = fs::last_write_time(path, failed);
    if (failed) {
        return identity;
    }
    return identity + ' ' + std::to_string(size) + ' ' +
           std::to_string(written.time_since_epoch().count());
}

std::string outputWrittenMeanwhile(const std::string& type, const std::string& path,
                                   const std::string& before) {
    const std::string now = outputStamp(path);  // "" for a file written through
    if (now.empty() || now == before) {
        return {};
    }
    const std::string at = changedAt(path);
    return "the " + type + " output " + path + " was written by another run while this one ran" +
           (at.empty() ? "" : " (at " + at + ")") + ": this run's replaces it";
}

}  // namespace runner
}  // namespace robottestingframework
