// A shared library opened at run time. One header; the platform code is in
// shared_library-posix.cpp (dlopen) and shared_library-windows.cpp (LoadLibrary); what they
// share in shared_library.cpp.
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {
namespace plugin {

class SharedLibrary {
public:
    SharedLibrary() = default;
    ~SharedLibrary();
    SharedLibrary(const SharedLibrary&) = delete;
    SharedLibrary& operator=(const SharedLibrary&) = delete;

    // Opens `path` with all its symbols resolved now and kept private to it. On failure returns
    // false and error() holds the platform loader's own words.
    bool open(const std::string& path);
    void close();
    bool isOpen() const { return handle_ != nullptr; }

    // The address of `name`, or nullptr (with error() set) when the library does not export it.
    void* symbol(const char* name);
    const std::string& error() const { return error_; }

    // How the platform names libraries: "lib" and ".so" on Linux.
    static const char* prefix();
    static const char* suffix();
    // The folders the platform's loader searches for a bare library name, in its order:
    // LD_LIBRARY_PATH, then the system's folders. The folder holding this library comes
    // before the system's, so the project's own plug-ins are found from build and install trees.
    static std::vector<std::string> searchPath();

private:
    // The folder holding this library (RTF_dll), or "" (per platform).
    static std::string ownFolder();

    void* handle_ = nullptr;
    std::string error_;
};

}  // namespace plugin
}  // namespace robottestingframework
