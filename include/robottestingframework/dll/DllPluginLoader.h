// Loads test and fixture plug-ins from shared libraries (see Plugin.h).
#pragma once

#include <memory>
#include <string>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestCase.h>

namespace robottestingframework {
namespace plugin {

class SharedLibrary;

// Owns the library and the object it made; both go when the loader is closed or destroyed.
class DllPluginLoader {
public:
    DllPluginLoader();
    ~DllPluginLoader();
    DllPluginLoader(const DllPluginLoader&) = delete;
    DllPluginLoader& operator=(const DllPluginLoader&) = delete;

    // Loads `filename` (a path) and makes its test case. nullptr on failure: see getLastError().
    TestCase* open(const std::string& filename);
    void close();
    std::string getLastError() const { return error_; }

private:
    std::unique_ptr<SharedLibrary> library_;
    void* object_ = nullptr;
    void (*destroy_)(void*) = nullptr;
    std::string error_;
};

class DllFixturePluginLoader {
public:
    DllFixturePluginLoader();
    ~DllFixturePluginLoader();
    DllFixturePluginLoader(const DllFixturePluginLoader&) = delete;
    DllFixturePluginLoader& operator=(const DllFixturePluginLoader&) = delete;

    FixtureManager* open(const std::string& filename);
    void close();
    std::string getLastError() const { return error_; }

private:
    std::unique_ptr<SharedLibrary> library_;
    void* object_ = nullptr;
    void (*destroy_)(void*) = nullptr;
    std::string error_;
};

// Finds a plug-in by path or bare name: `name` as given if it has a folder part; otherwise
// next to `besideDir` first, then the library search path (LD_LIBRARY_PATH, the loader's
// default folders), trying the name as is and with the `lib` prefix and platform suffix added.
// Returns the path found, made absolute (the dynamic loader would look a bare name up on the
// library path), or an empty string with `searched` saying why: the places tried, or what the
// path is when it exists but is no file (a folder, a FIFO, a device).
std::string findPlugin(const std::string& name, const std::string& besideDir,
                       std::string* searched = nullptr);

}  // namespace plugin
}  // namespace robottestingframework
