#include "reporters/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "reporters/standard_output.h"

// What every platform shares; what the system does for AtomicFile (opening the file, writing,
// closing, renaming) is in atomic_file-<platform>.cpp.
namespace robottestingframework {
namespace reporters {

AtomicFile::~AtomicFile() {
    discard();
}

void AtomicFile::discard() {
    if (fd_ >= 0) {
        closeFile(fd_);
        fd_ = -1;
    }
    if (!temporary_.empty()) {
        std::remove(temporary_.c_str());
        temporary_.clear();
    }
}

bool AtomicFile::open(const std::string& filename, std::string& error) {
    discard();
    filename_ = filename;
    writeErrno_ = 0;
    if (!namesStandardOutput(filename)) {
        return openFile(filename, error);
    }
    // "-" (and /dev/stdout on POSIX): the standard output as the runner was given it (a pipe
    // too, where /dev/stdout's link leads nowhere), written through.
    fd_ = openStandardOutput();
    if (fd_ < 0) {
        error = "cannot write " + filename + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

bool AtomicFile::openTemporary(const std::string& target, std::string& error) {
    target_ = target;
    temporary_ = target + ".tmp." + processId();
    fd_ = createFile(temporary_);
    if (fd_ < 0) {
        const int code = errno;
        temporary_.clear();  // not ours: nothing to remove
        error = "cannot write " + filename_ + ": " + std::strerror(code);
        return false;
    }
    return true;
}

bool AtomicFile::write(const char* data, std::size_t size) {
    if (fd_ < 0 || writeErrno_ != 0) {
        return false;
    }
    std::size_t done = 0;
    while (done < size) {
        const long wrote = writeSome(fd_, data + done, size - done);
        if (wrote <= 0) {
            writeErrno_ = wrote < 0 ? errno : EIO;
            return false;
        }
        done += static_cast<std::size_t>(wrote);
    }
    return true;
}

bool AtomicFile::commit(std::string& error) {
    if (fd_ < 0) {
        error = "cannot write " + filename_ + ": " + std::strerror(EBADF);
        return false;
    }
    int code = writeErrno_;
    const int fd = fd_;
    fd_ = -1;
    if (closeFile(fd) != 0 && code == 0) {
        code = errno;
    }
    if (code != 0) {
        error = "cannot write " + filename_ + ": " + std::strerror(code);
        discard();
        return false;
    }
    if (!temporary_.empty()) {
        const std::string why = replaceFile(temporary_, target_);
        if (!why.empty()) {
            error = "cannot rename a temporary file to " + filename_ + ": " + why;
            discard();
            return false;
        }
    }
    temporary_.clear();
    return true;
}

bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error) {
    AtomicFile file;
    if (!file.open(filename, error)) {
        return false;
    }
    file.write(content.data(), content.size());
    return file.commit(error);
}

void reportWriteError(const std::string& why, TestMessage* error) {
    if (error != nullptr) {
        error->setMessage(why);
    } else {
        std::fprintf(stderr, "robottestingframework: %s\n", why.c_str());
    }
}

bool writeReport(const std::string& filename, const std::string& content, TestMessage* error) {
    std::string why;
    if (writeFileAtomically(filename, content, why)) {
        return true;
    }
    reportWriteError(why, error);
    return false;
}

}  // namespace reporters
}  // namespace robottestingframework
