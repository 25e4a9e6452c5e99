// A plug-in library opened and checked, with its factory found: what makes and deletes the
// objects of one plug-in. DllPluginLoader and DllFixturePluginLoader make one object from one;
// the runner keeps one per plug-in path, so that a suite naming one plug-in 10 000 times does
// not open the library and look its symbols up 10 000 times.
#pragma once

#include <memory>
#include <string>

namespace robottestingframework {
namespace plugin {

class SharedLibrary;

enum class PluginKind { Test, Fixture };

class PluginFactory {
public:
    // The factory of `filename`, or nullptr with `error` naming the file and the reason (not a
    // library, not a plug-in, a plug-in of the other kind, another plug-in ABI).
    static std::shared_ptr<const PluginFactory> open(const std::string& filename, PluginKind kind,
                                                     std::string& error);
    ~PluginFactory();
    PluginFactory(const PluginFactory&) = delete;
    PluginFactory& operator=(const PluginFactory&) = delete;

    // One new object (a TestCase or a FixtureManager), or nullptr with `error` when its
    // constructor threw or the factory made none.
    void* make(std::string& error) const;
    // Deletes an object make() gave, with the library's own delete.
    void destroy(void* object) const;

private:
    PluginFactory() = default;

    std::unique_ptr<SharedLibrary> library_;
    std::string filename_;
    const char* what_ = "";  // "test" or "fixture", for messages
    void* (*create_)() = nullptr;
    void (*destroy_)(void*) = nullptr;
};

}  // namespace plugin
}  // namespace robottestingframework
