// Finds and loads RTF_web (the live page's library) for WebProgressListener, once per process.
#pragma once

#include <string>

#include "web/live_page.h"

namespace robottestingframework {
namespace web {

// RTF_web's factory, loaded from beside the RTF library (then from the library search path);
// nullptr with `error` saying which file could not be loaded and why. The library stays
// loaded until the process ends: the pages it made run its code.
OpenLivePage loadLivePageLibrary(std::string& error);

// What loadLivePageLibrary() asks of the platform (live_page_library-<platform>.cpp): RTF_web
// loaded, never to be unloaded (nullptr with `error` naming the file and the reason), and the
// address of one of its symbols (nullptr when it has none).
void* loadLivePageFile(std::string& error);
void* livePageSymbol(void* library, const char* name);

}  // namespace web
}  // namespace robottestingframework
