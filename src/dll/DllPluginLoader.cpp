#include <robottestingframework/dll/DllFixturePluginLoader.h>
#include <robottestingframework/dll/DllPluginLoader.h>
#include <robottestingframework/dll/Plugin.h>
#include <robottestingframework/dll/SharedLibraryFactory.h>

#include "dll/shared_library.h"

namespace robottestingframework {
namespace plugin {

namespace {

// The names ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN / _FIXTURE_PLUGIN export.
const char* const abiSymbol = "robottestingframework_plugin_abi";

struct Kind {
    const char* create;
    const char* destroy;
    const char* shlibppFactory;  // what RTF 2.x's macros export (an SHLIBPP factory)
    const char* what;            // "test", for messages
    const char* other;           // the other kind's factory, to tell a fixture given as a test
    const char* otherShlibppFactory;
    const char* otherWhat;
};
const Kind testKind{"robottestingframework_create_test",
                    "robottestingframework_destroy_test",
                    ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME,
                    "test",
                    "robottestingframework_create_fixture",
                    ROBOTTESTINGFRAMEWORK_FIXTURE_FACTORY_NAME,
                    "fixture"};
const Kind fixtureKind{"robottestingframework_create_fixture",
                       "robottestingframework_destroy_fixture",
                       ROBOTTESTINGFRAMEWORK_FIXTURE_FACTORY_NAME,
                       "fixture",
                       "robottestingframework_create_test",
                       ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME,
                       "test"};

// A library built with RTF 2.x's macros (or SHLIBPP_DEFINE_SHARED_SUBCLASS with RTF 2.x's
// factory name) has no ABI symbol, only the SHLIBPP factory: its hooks make and delete the
// object. false (and `error`) when the factory does not answer as one.
bool shlibppHooks(SharedLibrary& library, const std::string& filename, const Kind& kind,
                  void* (*&create)(), void (*&destroy)(void*), std::string& error) {
    void* factory = library.symbol(kind.shlibppFactory);
    if (factory == nullptr) {
        return false;
    }
    shlibpp::SharedLibraryFactory checked;
    if (!checked.useFactoryFunction(factory)) {
        error = "'" + filename + "': " + checked.getError();
        return false;
    }
    create = checked.getApi().create;
    destroy = checked.getApi().destroy;
    return true;
}

// Opens `filename` and makes one object with its factory. Returns nullptr and sets `error`
// (naming the file, and in the loader's words) on failure.
void* openPlugin(const std::string& filename, const Kind& kind,
                 std::unique_ptr<SharedLibrary>& library, void (*&destroy)(void*),
                 std::string& error) {
    error.clear();
    auto opened = std::make_unique<SharedLibrary>();
    if (!opened->open(filename)) {
        error = "cannot load '" + filename + "': " + opened->error();
        return nullptr;
    }
    auto abi = reinterpret_cast<int (*)()>(opened->symbol(abiSymbol));
    void* (*create)() = nullptr;
    void (*destroyer)(void*) = nullptr;
    if (abi == nullptr) {
        std::string reason = opened->error();
        if (shlibppHooks(*opened, filename, kind, create, destroyer, error)) {
            // made with RTF 2.x's macros: loaded through its factory below
        } else if (!error.empty()) {
            return nullptr;
        } else if (opened->symbol(kind.otherShlibppFactory) != nullptr) {
            error = "'" + filename + "' is not a " + kind.what + " plug-in; it is a " +
                    kind.otherWhat + " plug-in";
            return nullptr;
        } else {
            error = "'" + filename + "' is not a Robot Testing Framework plug-in (" + reason +
                    "); build it with ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN";
            return nullptr;
        }
    } else if (abi() != ROBOTTESTINGFRAMEWORK_PLUGIN_ABI) {
        error = "'" + filename + "' was built for plug-in ABI " + std::to_string(abi()) +
                ", this runner loads ABI " + std::to_string(ROBOTTESTINGFRAMEWORK_PLUGIN_ABI) +
                "; rebuild it";
        return nullptr;
    } else {
        create = reinterpret_cast<void* (*)()>(opened->symbol(kind.create));
        destroyer = reinterpret_cast<void (*)(void*)>(opened->symbol(kind.destroy));
        if (create == nullptr || destroyer == nullptr) {
            error =
                "'" + filename + "' is not a " + kind.what + " plug-in (" + opened->error() + ")";
            if (opened->symbol(kind.other) != nullptr) {
                error += "; it is a " + std::string(kind.otherWhat) + " plug-in";
            }
            return nullptr;
        }
    }
    void* object = nullptr;
    try {
        object = create();
    } catch (const std::exception& e) {
        error = "the constructor of the " + std::string(kind.what) + " in '" + filename +
                "' threw: " + e.what();
        return nullptr;
    } catch (...) {
        error = "the constructor of the " + std::string(kind.what) + " in '" + filename +
                "' threw an exception";
        return nullptr;
    }
    if (object == nullptr) {
        error = "the factory of '" + filename + "' returned no object";
        return nullptr;
    }
    library = std::move(opened);
    destroy = destroyer;
    error.clear();
    return object;
}

void closePlugin(std::unique_ptr<SharedLibrary>& library, void*& object, void (*&destroy)(void*)) {
    // The object's code lives in the library: destroy it first, with the library's own delete.
    if (object != nullptr && destroy != nullptr) {
        destroy(object);
    }
    object = nullptr;
    destroy = nullptr;
    library.reset();
}

}  // namespace

DllPluginLoader::DllPluginLoader() = default;
DllPluginLoader::~DllPluginLoader() {
    close();
}

TestCase* DllPluginLoader::open(const std::string filename) {
    close();
    object_ = openPlugin(filename, testKind, library_, destroy_, error_);
    return static_cast<TestCase*>(object_);
}

void DllPluginLoader::close() {
    closePlugin(library_, object_, destroy_);
}

DllFixturePluginLoader::DllFixturePluginLoader() = default;
DllFixturePluginLoader::~DllFixturePluginLoader() {
    close();
}

FixtureManager* DllFixturePluginLoader::open(const std::string filename) {
    close();
    object_ = openPlugin(filename, fixtureKind, library_, destroy_, error_);
    return static_cast<FixtureManager*>(object_);
}

void DllFixturePluginLoader::close() {
    closePlugin(library_, object_, destroy_);
}

}  // namespace plugin
}  // namespace robottestingframework
