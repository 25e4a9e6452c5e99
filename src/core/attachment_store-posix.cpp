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
    if (!copyBytes(input.get(), outputFile.get(), size, copyError)) {
        ::unlink((folder / storedName).c_str());
        error = what + copyError;
        return false;
    }
    describeStored(folder, storedName, source, description, size, attachment);
    return true;
}

}  // namespace robottestingframework
