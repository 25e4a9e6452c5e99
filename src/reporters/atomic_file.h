// Writing a report file whole or not at all: a temporary name beside it, then a rename. A
// symbolic link is followed (its target is written, the link stays); a FIFO or a character
// device (/dev/stdout, /dev/null) is written through, never replaced; anything else that is not
// a regular file (a folder, a socket) is refused.
#pragma once

#include <cstddef>
#include <string>

#include <robottestingframework/TestMessage.h>

namespace robottestingframework {
namespace reporters {

// Empty when `filename` can be an output (a file, a FIFO, a character device, or nothing yet);
// else "FILE is a folder; ..." for the runner to refuse before the run.
std::string notAnOutputFile(const std::string& filename);

// A file written a block at a time, whole or not at all: open() creates a temporary file
// beside it (or opens the FIFO or device it is), write() adds to it, commit() renames the
// temporary file into place. Dropped without commit(), it leaves nothing behind. Errors name
// the file and give the system's reason.
class AtomicFile {
public:
    AtomicFile() = default;
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    bool open(const std::string& filename, std::string& error);
    // False once a write failed; commit() then says why.
    bool write(const char* data, std::size_t size);
    bool commit(std::string& error);

private:
    void discard();
    // The file itself (not the standard output): a FIFO or a device written through, else a
    // temporary file beside the target (openTemporary). Per platform.
    bool openFile(const std::string& filename, std::string& error);
    bool openTemporary(const std::string& target, std::string& error);

    // What each platform gives (atomic_file-<platform>.cpp). The errors are in errno.
    static int createFile(const std::string& path);  // a new file, write only; -1 on failure
    static long writeSome(int fd, const char* data, std::size_t size);  // < 0 on failure
    static int closeFile(int fd);                                       // 0, or -1 on failure
    static std::string processId();
    // Puts `temporary` in the place of `target`: empty, or the system's reason.
    static std::string replaceFile(const std::string& temporary, const std::string& target);

    std::string filename_;
    std::string target_;     // the file the temporary one replaces
    std::string temporary_;  // empty: a FIFO or a device, written through
    int fd_ = -1;
    int writeErrno_ = 0;
};

// On failure returns false, leaves no file behind and puts the file name and the system's
// reason in `error`.
bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error);

// What the outputters' write() does: the same, with the reason in `error` when given, on
// stderr otherwise.
bool writeReport(const std::string& filename, const std::string& content, TestMessage* error);

// How writeReport() tells `why` it could not write: into `error` when given, else on stderr.
void reportWriteError(const std::string& why, TestMessage* error);

}  // namespace reporters
}  // namespace robottestingframework
