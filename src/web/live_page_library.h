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

}  // namespace web
}  // namespace robottestingframework
