#include "runner/cli/attachments_folder.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "platform/environment.h"
#include "reporters/standard_output.h"

namespace fs = std::filesystem;

namespace robottestingframework {
namespace runner {

namespace {

constexpr const char* kVariable = "RTF_ATTACHMENTS_DIR";

// Beside the first output that is a file (or will be): not a device or a FIFO, not the standard
// output ("-", /dev/stdout).
fs::path reportsFolder(const Options& options) {
    if (!options.noOutput) {
        for (const OutputRequest& output : options.outputs) {
            if (reporters::namesStandardOutput(output.file)) {
                continue;
            }
            std::error_code failed;
            const fs::file_status status = fs::status(output.file, failed);
            if (!failed && fs::exists(status) && !fs::is_regular_file(status)) {
                continue;
            }
            return fs::absolute(output.file, failed).parent_path();
        }
    }
    std::error_code failed;
    return fs::current_path(failed);
}

}  // namespace

bool prepareAttachmentsFolder(const Options& options, std::string& error) {
    const char* named = std::getenv(kVariable);
    if (named != nullptr && *named != '\0') {
        return true;
    }
    const fs::path folder = reportsFolder(options) / "rtf-attachments";
    std::error_code failed;
    const fs::file_status status = fs::symlink_status(folder, failed);
    if (fs::is_symlink(status)) {
        error = "the attachments folder " + folder.string() + " is a symbolic link";
        return false;
    }
    // Made by the first attachment (a run without any writes nothing). The last run's files
    // go: what a report links is this run's. Only plain files, not what the user put there.
    if (fs::is_directory(status)) {
        for (const auto& entry : fs::directory_iterator(folder, failed)) {
            std::error_code ignored;
            if (entry.is_regular_file(ignored) && !entry.is_symlink(ignored)) {
                fs::remove(entry.path(), ignored);
            }
        }
        if (failed) {
            error =
                "cannot empty the attachments folder " + folder.string() + ": " + failed.message();
            return false;
        }
    }
    platform::setEnvironment(kVariable, folder.string());
    return true;
}

}  // namespace runner
}  // namespace robottestingframework
