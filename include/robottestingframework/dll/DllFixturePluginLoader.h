// Loads fixture-manager plug-ins from shared libraries
// (ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN in Plugin.h), as RTF 2.x's
// plugin::DllFixturePluginLoader does.
#pragma once

#include <memory>
#include <string>

#include <robottestingframework/FixtureManager.h>

namespace robottestingframework {
namespace plugin {

class PluginFactory;

// Owns the library and the fixture it made; both go when the loader is closed or destroyed.
class DllFixturePluginLoader {
public:
    DllFixturePluginLoader();
    virtual ~DllFixturePluginLoader();
    DllFixturePluginLoader(const DllFixturePluginLoader&) = delete;
    DllFixturePluginLoader& operator=(const DllFixturePluginLoader&) = delete;

    // Loads `filename` (a path) and makes its fixture manager. nullptr on failure, with
    // getLastError() naming the file and the reason; nothing is printed.
    FixtureManager* open(const std::string filename);
    void close();
    const std::string getLastError() { return error_; }

private:
    std::shared_ptr<const PluginFactory> factory_;
    void* object_ = nullptr;
    std::string error_;
};

}  // namespace plugin
}  // namespace robottestingframework
