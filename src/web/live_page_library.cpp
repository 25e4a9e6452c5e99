#include "web/live_page_library.h"

#include <mutex>

// What every platform shares; loading the file is in live_page_library-<platform>.cpp.
namespace robottestingframework {
namespace web {

namespace {

struct Loaded {
    OpenLivePage open = nullptr;
    std::string error;
};

Loaded load() {
    Loaded loaded;
    void* library = loadLivePageFile(loaded.error);
    if (library == nullptr) {
        return loaded;
    }
    void* symbol = livePageSymbol(library, openLivePageSymbol);
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
