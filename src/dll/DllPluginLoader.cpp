#include <robottestingframework/dll/DllFixturePluginLoader.h>
#include <robottestingframework/dll/DllPluginLoader.h>

#include "dll/plugin_factory.h"

namespace robottestingframework {
namespace plugin {

namespace {

// Opens `filename` and makes one object with its factory. Returns nullptr and sets `error`
// (naming the file, and in the loader's words) on failure.
void* openPlugin(const std::string& filename, PluginKind kind,
                 std::shared_ptr<const PluginFactory>& factory, std::string& error) {
    std::shared_ptr<const PluginFactory> opened = PluginFactory::open(filename, kind, error);
    if (opened == nullptr) {
        return nullptr;
    }
    void* object = opened->make(error);
    if (object != nullptr) {
        factory = std::move(opened);
    }
    return object;
}

void closePlugin(std::shared_ptr<const PluginFactory>& factory, void*& object) {
    // The object's code lives in the library: destroy it first, with the library's own delete.
    if (factory != nullptr) {
        factory->destroy(object);
    }
    object = nullptr;
    factory.reset();
}

}  // namespace

DllPluginLoader::DllPluginLoader() = default;
DllPluginLoader::~DllPluginLoader() {
    close();
}

TestCase* DllPluginLoader::open(const std::string filename) {
    close();
    object_ = openPlugin(filename, PluginKind::Test, factory_, error_);
    return static_cast<TestCase*>(object_);
}

void DllPluginLoader::close() {
    closePlugin(factory_, object_);
}

DllFixturePluginLoader::DllFixturePluginLoader() = default;
DllFixturePluginLoader::~DllFixturePluginLoader() {
    close();
}

FixtureManager* DllFixturePluginLoader::open(const std::string filename) {
    close();
    object_ = openPlugin(filename, PluginKind::Fixture, factory_, error_);
    return static_cast<FixtureManager*>(object_);
}

void DllFixturePluginLoader::close() {
    closePlugin(factory_, object_);
}

}  // namespace plugin
}  // namespace robottestingframework
