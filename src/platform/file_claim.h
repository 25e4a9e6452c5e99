// A claim on a file among the processes of this machine: the file one process at a time may
// write (a world's process log: two runs started in one folder wrote one log at once, each
// emptying the other's, and each run attached lines of the other's world). An advisory lock,
// held while the claim lives: flock() on POSIX, LockFileEx() on a byte past any end on Windows
// (the file's own bytes stay free to write through other handles). It neither writes nor
// empties the file.
#pragma once

#include <cstdint>
#include <string>

namespace robottestingframework {
namespace platform {

class FileClaim {
public:
    FileClaim() = default;
    ~FileClaim() { release(); }
    FileClaim(const FileClaim&) = delete;
    FileClaim& operator=(const FileClaim&) = delete;

    // Claims `path` (made empty if missing). False with `busy` set when another holds it (another
    // process, or another claim of this one); false with `error` set when it cannot be opened or
    // locked. A claim held before is let go first.
    bool take(const std::string& path, bool& busy, std::string& error);
    void release();
    bool held() const { return handle_ != -1; }

private:
    std::intptr_t handle_ = -1;  // a descriptor on POSIX, a HANDLE on Windows
};

}  // namespace platform
}  // namespace robottestingframework
