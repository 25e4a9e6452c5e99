#include "attachment_rules.h"
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

// Copies `from` to its end, whatever its size said: a file of /proc or /sys says 0 and has
// more. Stops with `error` once more than `limit` bytes came; `copied` gets how many did.
bool copyBytes(int from, int to, std::uint64_t limit, std::uint64_t& copied, std::string& error) {
    char buffer[64 * 1024];
    copied = 0;
    for (;;) {
        const ssize_t got = ::read(from, buffer, sizeof(buffer));
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got < 0) {
            error = std::strerror(errno);
            return false;
        }
        if (got == 0) {
            return true;
        }
        copied += static_cast<std::uint64_t>(got);
        if (copied > limit) {
            error = "it has more than the " + std::to_string(limit) + " bytes a file may have (" +
                    kAttachmentFileLimitVariable + ")";
            return false;
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
    }
}

}  // namespace

bool storeAttachment(const std::string& source, const std::string& description,
                     Attachment& attachment, std::string& error) {
    const std::string what = "cannot attach '" + source + "': ";
    std::uint64_t fileLimit = 0;
    std::uint64_t runLimit = 0;
    std::string problem;
    if (!attachmentLimits(fileLimit, runLimit, problem)) {
        error = what + problem;
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
    problem = fileOverLimit(size, fileLimit);
    fs::path folder;
    if (!problem.empty() || !attachmentsFolder(folder, problem)) {
        error = what + problem;
        return false;
    }
    // One writer at a time across the run's processes: the folder's content is the account.
    Descriptor lock(::open((folder / ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644));
    if (lock.get() < 0 || ::flock(lock.get(), LOCK_EX) != 0) {
        error = what + "cannot lock " + (folder / ".lock").string() + ": " + std::strerror(errno);
        return false;
    }
    std::uint64_t files = 0;
    problem = runOverLimit(folder, size, runLimit, files);
    if (!problem.empty()) {
        error = what + problem;
        return false;
    }
    std::string storedName;
    int output = -1;
    for (std::uint64_t number = files + 1; output < 0; ++number) {
        storedName = storedNameOf(source, number);
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
    std::uint64_t copied = 0;
    if (!copyBytes(input.get(), outputFile.get(), fileLimit, copied, copyError)) {
        ::unlink((folder / storedName).c_str());
        error = what + copyError;
        return false;
    }
    if (copied > size) {
        // It had more than its size said (/proc): the run's account again, with the copy in.
        problem = runOverLimit(folder, 0, runLimit, files);
        if (!problem.empty()) {
            ::unlink((folder / storedName).c_str());
            error = what + problem;
            return false;
        }
    }
    describeStored(folder, storedName, source, description, copied, attachment);
    return true;
}

}  // namespace robottestingframework
