// Loads test plug-ins from shared libraries (see Plugin.h), and finds plug-ins by name.
#pragma once

#include <memory>
#include <string>

#include <robottestingframework/PluginLoader.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/DllFixturePluginLoader.h>

namespace robottestingframework {
namespace plugin {

class PluginFactory;

// Owns the library and the object it made; both go when the loader is closed or destroyed.
class DllPluginLoader : public PluginLoader {
public:
    DllPluginLoader();
    ~DllPluginLoader() override;

    // Loads `filename` (a path) and makes its test case. nullptr on failure: see getLastError().
    // Libraries built with RTF 2.x's ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN load too.
    TestCase* open(const std::string filename) override;
    void close() override;
    const std::string getLastError() override { return error_; }

private:
    std::shared_ptr<const PluginFactory> factory_;
    void* object_ = nullptr;
    std::string error_;
};

// Finds a plug-in by path or bare name: `name` as given if it has a folder part; otherwise
// next to `besideDir` first, then the folders of RTF_PLUGIN_PATH (in order; the runner puts
// its --plugin-path folders first), then the library search path (LD_LIBRARY_PATH, the
// loader's default folders), trying the name as is and with the `lib` prefix and platform
// suffix added. Returns the path found, made absolute (the dynamic loader would look a bare
// name up on the library path), or an empty string with `searched` saying why: the places
// tried, or what the path is when it exists but is no file (a folder, a FIFO, a device).
std::string findPlugin(const std::string& name, const std::string& besideDir,
                       std::string* searched = nullptr);

}  // namespace plugin
}  // namespace robottestingframework
