#include "dll/shared_library.h"

#include <dlfcn.h>

#include <cstdlib>

#include "dll/rtf2_library.h"

namespace robottestingframework {
namespace plugin {

namespace {

std::string lastError(const char* fallback) {
    const char* text = ::dlerror();
    return text != nullptr ? text : fallback;
}

}  // namespace

bool SharedLibrary::open(const std::string& path) {
    close();
    // Never into this process: RTF 2.x's library would clash with this one (SIGABRT at best).
    const std::string rtf2 = rtf2LibraryNeeded(path);
    if (!rtf2.empty()) {
        error_ = builtAgainstRtf2(path, rtf2);
        return false;
    }
    ::dlerror();
    // RTLD_LOCAL: two plug-ins defining the same class names do not clash.
    handle_ = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_ == nullptr) {
        error_ = lastError("unknown dlopen error");
        return false;
    }
    error_.clear();
    return true;
}

void SharedLibrary::close() {
    if (handle_ != nullptr) {
        ::dlclose(handle_);
        handle_ = nullptr;
    }
}

void* SharedLibrary::symbol(const char* name) {
    if (handle_ == nullptr) {
        error_ = "the library is not open";
        return nullptr;
    }
    ::dlerror();
    void* address = ::dlsym(handle_, name);
    if (address == nullptr) {
        error_ = lastError("symbol not found");
    }
    return address;
}

std::string SharedLibrary::ownFolder() {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&SharedLibrary::ownFolder), &info) == 0 ||
        info.dli_fname == nullptr) {
        return {};
    }
    std::string path = info.dli_fname;
    std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

}  // namespace plugin
}  // namespace robottestingframework
