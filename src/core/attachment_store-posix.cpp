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

#include "platform/file_descriptor.h"

namespace fs = std::filesystem;

namespace robottestingframework {

namespace {

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

bool storeCopy(AttachmentSteps& steps, const std::string& description, Attachment& attachment) {
    const std::string& source = steps.source();
    platform::FileDescriptor input(::open(source.c_str(), O_RDONLY | O_CLOEXEC));
    struct stat info {};
    if (!input.valid() || ::fstat(input.get(), &info) != 0) {
        return steps.fail(std::strerror(errno));
    }
    if (!S_ISREG(info.st_mode)) {
        return steps.fail("not a regular file");
    }
    const auto size = static_cast<std::uint64_t>(info.st_size);
    if (!steps.admitFile(size)) {
        return false;
    }
    // One writer at a time across the run's processes: the folder's content is the account.
    const fs::path lockName = steps.folder() / ".lock";
    platform::FileDescriptor lock(::open(lockName.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644));
    if (!lock.valid() || ::flock(lock.get(), LOCK_EX) != 0) {
        return steps.fail("cannot lock " + lockName.string() + ": " + std::strerror(errno));
    }
    if (!steps.admitRun(size)) {
        return false;
    }
    platform::FileDescriptor output;
    while (!output.valid()) {
        const fs::path stored = steps.nextStored();
        output.reset(::open(stored.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
        if (!output.valid() && errno != EEXIST) {
            return steps.fail("cannot write " + stored.string() + ": " + std::strerror(errno));
        }
    }
    std::string copyError;
    std::uint64_t copied = 0;
    if (!copyBytes(input.get(), output.get(), steps.fileLimit(), copied, copyError)) {
        steps.discardStored();
        return steps.fail(copyError);
    }
    // It had more than its size said (/proc): the run's account again, with the copy in.
    if (copied > size && !steps.admitRun(0)) {
        steps.discardStored();
        return false;
    }
    steps.describe(description, copied, attachment);
    return true;
}

}  // namespace robottestingframework
