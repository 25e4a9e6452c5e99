#include "web/live_page_library.h"

#include <dlfcn.h>

#include <string>

namespace robottestingframework {
namespace web {

namespace {

// The folder this library (RTF) was loaded from: RTF_web is installed and built beside it.
std::string ownFolder() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&loadLivePageLibrary), &info) == 0 ||
        info.dli_fname == nullptr) {
        return {};
    }
    const std::string path = info.dli_fname;
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

}  // namespace

void* loadLivePageFile(std::string& error) {
    const std::string name = RTF_WEB_LIBRARY_FILE;
    const std::string beside = ownFolder() + name;
    void* handle = dlopen(beside.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        const std::string besideError = dlerror();
        handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            error = "cannot load the live page's library " + beside + ": " + besideError;
        }
    }
    return handle;
}

void* livePageSymbol(void* library, const char* name) {
    return dlsym(library, name);
}

}  // namespace web
}  // namespace robottestingframework
