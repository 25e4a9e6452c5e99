#include "attachment_store.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace robottestingframework {

namespace {

class Descriptor {
public:
    explicit Descriptor(int fd) : fd_(fd) {}
    ~Descriptor() {
        if (fd_ >= 0) {
            ::close(fd_);
        }
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

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

// The bytes already stored this run, and how many files.
void usageOf(const fs::path& folder, std::uint64_t& bytes, std::uint64_t& files) {
    bytes = 0;
    files = 0;
    std::error_code ignored;
    for (const auto& entry : fs::directory_iterator(folder, ignored)) {
        if (entry.path().filename() == ".lock") {
            continue;
        }
        std::error_code sizeError;
        const auto size = entry.is_regular_file(sizeError) ? entry.file_size(sizeError) : 0;
        bytes += sizeError ? 0 : size;
        ++files;
    }
}

bool copyBytes(int from, int to, std::uint64_t size, std::string& error) {
    char buffer[64 * 1024];
    std::uint64_t left = size;
    while (left > 0) {
        const ssize_t got = ::read(from, buffer, left < sizeof(buffer) ? left : sizeof(buffer));
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got < 0) {
            error = std::strerror(errno);
            return false;
        }
        if (got == 0) {
            break;  // the file shrank while copied: keep what there was
        }
        for (ssize_t done = 0; done < got;) {
            const ssize_t put = ::write(to, buffer + done, static_cast<size_t>(got - done));
            if (put < 0 && errno == EINTR) {
                continue;
            }
            if (put < 0) {
                error = std::strerror(errno);
                return false;
            }
            done += put;
        }
        left -= static_cast<std::uint64_t>(got);
    }
    return true;
}

}  // namespace

bool storeAttachment(const std::string& source, const std::string& description,
                     Attachment& attachment, std::string& error) {
    const std::string what = "cannot attach '" + source + "': ";
    std::uint64_t fileLimit = 0;
    std::uint64_t runLimit = 0;
    std::string limitError;
    if (!limitFrom(kAttachmentFileLimitVariable, kDefaultAttachmentFileLimit, fileLimit,
                   limitError) ||
        !limitFrom(kAttachmentRunLimitVariable, kDefaultAttachmentRunLimit, runLimit, limitError)) {
        error = what + limitError;
        return false;
    }
    Descriptor input(::open(source.c_str(), O_RDONLY | O_CLOEXEC));
    struct stat info {};
    if (input.get() < 0 || ::fstat(input.get(), &info) != 0) {
        error = what + std::strerror(errno);
        return false;
    }
    if (!S_ISREG(info.st_mode)) {
        error = what + "not a regular file";
        return false;
    }
    const auto size = static_cast<std::uint64_t>(info.st_size);
    if (size > fileLimit) {
        error = what + "it is " + std::to_string(size) + " bytes, more than the " +
                std::to_string(fileLimit) + " bytes a file may have (" +
                kAttachmentFileLimitVariable + ")";
        return false;
    }
    const char* named = std::getenv(kAttachmentsFolderVariable);
    std::error_code failed;
    fs::path folder =
        fs::absolute(named != nullptr && *named != '\0' ? named : "rtf-attachments", failed);
    folder = folder.lexically_normal();
    if (folder.filename().empty()) {
        folder = folder.parent_path();  // "out/" names the folder "out"
    }
    fs::create_directories(folder, failed);
    if (failed) {
        error = what + "cannot make the folder " + folder.string() + ": " + failed.message();
        return false;
    }
    // One writer at a time across the run's processes: the folder's content is the account.
    Descriptor lock(::open((folder / ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644));
    if (lock.get() < 0 || ::flock(lock.get(), LOCK_EX) != 0) {
        error = what + "cannot lock " + (folder / ".lock").string() + ": " + std::strerror(errno);
        return false;
    }
    std::uint64_t used = 0;
    std::uint64_t files = 0;
    usageOf(folder, used, files);
    if (used + size > runLimit) {
        error = what + "the run's attachments would take " + std::to_string(used + size) +
                " bytes, more than the " + std::to_string(runLimit) + " bytes allowed (" +
                kAttachmentRunLimitVariable + ")";
        return false;
    }
    const std::string original = fs::path(source).filename().string();
    std::string storedName;
    int output = -1;
    for (std::uint64_t number = files + 1; output < 0; ++number) {
        storedName = std::to_string(number) + "-" + original;
        output =
            ::open((folder / storedName).c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        if (output < 0 && errno != EEXIST) {
            error = what + "cannot write " + (folder / storedName).string() + ": " +
                    std::strerror(errno);
            return false;
        }
    }
    Descriptor outputFile(output);
    std::string copyError;
    if (!copyBytes(input.get(), outputFile.get(), size, copyError)) {
        ::unlink((folder / storedName).c_str());
        error = what + copyError;
        return false;
    }
    attachment.path = (folder.filename() / storedName).string();
    attachment.absolutePath = (folder / storedName).string();
    attachment.description = description;
    attachment.originalName = original;
    attachment.size = size;
    return true;
}

}  // namespace robottestingframework
