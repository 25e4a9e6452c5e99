#include "attachment_rules.h"

#include <cerrno>
#include <cstdlib>
#include <system_error>

#include "attachment_store.h"
#include "core/text_safety.h"

namespace fs = std::filesystem;

namespace robottestingframework {

namespace {

// A limit from the environment: the default when unset; false when set to anything but a
// whole number of bytes.
bool limitFrom(const char* variable, std::uint64_t fallback, std::uint64_t& limit,
               std::string& error) {
    const char* text = std::getenv(variable);
    if (text == nullptr || *text == '\0') {
        limit = fallback;
        return true;
    }
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text, &end, 10);
    if (errno != 0 || *end != '\0' || text[0] == '-') {
        error = std::string(variable) + "='" + text + "' is not a number of bytes";
        return false;
    }
    limit = value;
    return true;
}

}  // namespace

bool attachmentLimits(std::uint64_t& fileLimit, std::uint64_t& runLimit, std::string& error) {
    return limitFrom(kAttachmentFileLimitVariable, kDefaultAttachmentFileLimit, fileLimit, error) &&
           limitFrom(kAttachmentRunLimitVariable, kDefaultAttachmentRunLimit, runLimit, error);
}

std::string fileOverLimit(std::uint64_t size, std::uint64_t fileLimit) {
    if (size <= fileLimit) {
        return {};
    }
    return "it is " + std::to_string(size) + " bytes, more than the " + std::to_string(fileLimit) +
           " bytes a file may have (" + kAttachmentFileLimitVariable + ")";
}

bool attachmentsFolder(fs::path& folder, std::string& error) {
    const char* named = std::getenv(kAttachmentsFolderVariable);
    std::error_code failed;
    folder = fs::absolute(named != nullptr && *named != '\0' ? named : "rtf-attachments", failed);
    folder = folder.lexically_normal();
    if (folder.filename().empty()) {
        folder = folder.parent_path();  // "out/" names the folder "out"
    }
    fs::create_directories(folder, failed);
    if (failed) {
        error = "cannot make the folder " + folder.string() + ": " + failed.message();
        return false;
    }
    return true;
}

std::string runOverLimit(const fs::path& folder, std::uint64_t size, std::uint64_t runLimit,
                         std::uint64_t& files) {
    std::uint64_t used = 0;
    files = 0;
    std::error_code ignored;
    for (const auto& entry : fs::directory_iterator(folder, ignored)) {
        if (entry.path().filename() == ".lock") {
            continue;
        }
        std::error_code sizeError;
        const auto bytes = entry.is_regular_file(sizeError) ? entry.file_size(sizeError) : 0;
        used += sizeError ? 0 : bytes;
        ++files;
    }
    if (used + size <= runLimit) {
        return {};
    }
    return "the run's attachments would take " + std::to_string(used + size) +
           " bytes, more than the " + std::to_string(runLimit) + " bytes allowed (" +
           kAttachmentRunLimitVariable + ")";
}

std::string storedNameOf(const std::string& source, std::uint64_t number) {
    return std::to_string(number) + "-" +
           reporters::safeFileName(fs::path(source).filename().string());
}

void describeStored(const fs::path& folder, const std::string& storedName,
                    const std::string& source, const std::string& description, std::uint64_t size,
                    Attachment& attachment) {
    attachment.path = (folder.filename() / storedName).generic_string();  // a link in reports
    attachment.absolutePath = (folder / storedName).string();
    attachment.description = description;
    attachment.originalName = fs::path(source).filename().string();
    attachment.size = size;
}

bool storeAttachment(const std::string& source, const std::string& description,
                     Attachment& attachment, std::string& error) {
    AttachmentSteps steps(source, error);
    return steps.readLimits() && storeCopy(steps, description, attachment);
}

AttachmentSteps::AttachmentSteps(const std::string& source, std::string& error)
    : source_(source), error_(error) {}

bool AttachmentSteps::readLimits() {
    std::string problem;
    return attachmentLimits(fileLimit_, runLimit_, problem) || fail(problem);
}

bool AttachmentSteps::admitFile(std::uint64_t size) {
    std::string problem = fileOverLimit(size, fileLimit_);
    return (problem.empty() && attachmentsFolder(folder_, problem)) || fail(problem);
}

bool AttachmentSteps::admitRun(std::uint64_t size) {
    const std::string problem = runOverLimit(folder_, size, runLimit_, files_);
    return problem.empty() || fail(problem);
}

fs::path AttachmentSteps::nextStored() {
    storedName_ = storedNameOf(source_, files_ + ++tried_);
    return folder_ / storedName_;
}

void AttachmentSteps::discardStored() {
    std::error_code ignored;
    fs::remove(folder_ / storedName_, ignored);
}

void AttachmentSteps::describe(const std::string& description, std::uint64_t size,
                               Attachment& attachment) {
    describeStored(folder_, storedName_, source_, description, size, attachment);
}

bool AttachmentSteps::fail(const std::string& why) {
    error_ = "cannot attach '" + source_ + "': " + why;
    return false;
}

}  // namespace robottestingframework
