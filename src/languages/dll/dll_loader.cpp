// C++ test and fixture plug-ins. The runner opens each plug-in's library once and keeps it, with
// its factory, for the rest of its run: a suite that names one plug-in 10 000 times makes its
// 10 000 tests from one factory instead of opening the library and looking its symbols up for
// each (that was an eighth of such a run in process). A plug-in's library stayed loaded between
// its tests before too: the loader keeps C++ libraries with unique symbols mapped after
// dlclose, and RTF 2.x held every test's library open for the whole run.
#include <mutex>
#include <unordered_map>

#include "dll/plugin_factory.h"
#include "languages/language_loaders.h"

namespace robottestingframework {
namespace languages {

namespace {

// The factory of `path`, opened on first use; nullptr with `error` when it is no plug-in of
// that kind (tried again next time: the file may be rebuilt while a long run goes on).
std::shared_ptr<const plugin::PluginFactory> factoryOf(const std::string& path,
                                                       plugin::PluginKind kind,
                                                       std::string& error) {
    static std::mutex mutex;  // in-process suites run on threads under -j
    static std::unordered_map<std::string, std::shared_ptr<const plugin::PluginFactory>>
        factories[2];
    std::lock_guard<std::mutex> lock(mutex);
    auto& known = factories[kind == plugin::PluginKind::Test ? 0 : 1];
    auto found = known.find(path);
    if (found != known.end()) {
        return found->second;
    }
    auto factory = plugin::PluginFactory::open(path, kind, error);
    if (factory != nullptr) {
        known.emplace(path, factory);
    }
    return factory;
}

template <typename T>
class LoadedPlugin : public Loaded<T> {
public:
    LoadedPlugin(std::shared_ptr<const plugin::PluginFactory> factory, void* object)
        : factory_(std::move(factory)), object_(static_cast<T*>(object)) {}
    ~LoadedPlugin() override { factory_->destroy(object_); }
    LoadedPlugin(const LoadedPlugin&) = delete;
    LoadedPlugin& operator=(const LoadedPlugin&) = delete;
    T* get() override { return object_; }

private:
    std::shared_ptr<const plugin::PluginFactory> factory_;
    T* object_;
};

template <typename T>
std::unique_ptr<Loaded<T>> load(const std::string& path, plugin::PluginKind kind,
                                std::string& error) {
    auto factory = factoryOf(path, kind, error);
    if (factory == nullptr) {
        return nullptr;
    }
    void* object = factory->make(error);
    if (object == nullptr) {
        return nullptr;
    }
    return std::make_unique<LoadedPlugin<T>>(std::move(factory), object);
}

}  // namespace

std::unique_ptr<LoadedTest> loadDllTest(const std::string& path, std::string& error) {
    return load<TestCase>(path, plugin::PluginKind::Test, error);
}

std::unique_ptr<LoadedFixture> loadDllFixture(const std::string& path, std::string& error) {
    return load<FixtureManager>(path, plugin::PluginKind::Fixture, error);
}

}  // namespace languages
}  // namespace robottestingframework
