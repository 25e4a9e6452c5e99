// C++ test and fixture plug-ins: the library stays loaded as long as the object lives.
#include <robottestingframework/dll/DllPluginLoader.h>

#include "languages/language_loaders.h"

namespace robottestingframework {
namespace languages {

namespace {

template <typename T, typename Loader>
class LoadedPlugin : public Loaded<T> {
public:
    bool open(const std::string& path, std::string& error) {
        object_ = loader_.open(path);
        if (object_ == nullptr) {
            error = loader_.getLastError();
        }
        return object_ != nullptr;
    }
    T* get() override { return object_; }

private:
    Loader loader_;
    T* object_ = nullptr;
};

template <typename T, typename Loader>
std::unique_ptr<Loaded<T>> load(const std::string& path, std::string& error) {
    auto loaded = std::make_unique<LoadedPlugin<T, Loader>>();
    if (!loaded->open(path, error)) {
        return nullptr;
    }
    return loaded;
}

}  // namespace

std::unique_ptr<LoadedTest> loadDllTest(const std::string& path, std::string& error) {
    return load<TestCase, plugin::DllPluginLoader>(path, error);
}

std::unique_ptr<LoadedFixture> loadDllFixture(const std::string& path, std::string& error) {
    return load<FixtureManager, plugin::DllFixturePluginLoader>(path, error);
}

}  // namespace languages
}  // namespace robottestingframework
