#include "web/live_page_library.h"

#include <dlfcn.h>

#include <mutex>

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

struct Loaded {
    OpenLivePage open = nullptr;
    std::string error;
};

Loaded load() {
    Loaded loaded;
    const std::string name = RTF_WEB_LIBRARY_FILE;
    const std::string beside = ownFolder() + name;
    void* handle = dlopen(beside.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        const std::string besideError = dlerror();
        handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            loaded.error = "cannot load the live page's library " + beside + ": " + besideError;
            return loaded;
        }
    }
    void* symbol = dlsym(handle, openLivePageSymbol);
    if (symbol == nullptr) {
        loaded.error = std::string("the live page's library has no ") + openLivePageSymbol;
        return loaded;
    }
    loaded.open = reinterpret_cast<OpenLivePage>(symbol);
    return loaded;
}

}  // namespace

OpenLivePage loadLivePageLibrary(std::string& error) {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = load(); });
    error = loaded.error;
    return loaded.open;
}

}  // namespace web
}  // namespace robottestingframework
