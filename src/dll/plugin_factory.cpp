#include "dll/plugin_factory.h"

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

}  // namespace

std::shared_ptr<const PluginFactory> PluginFactory::open(const std::string& filename,
                                                         PluginKind which, std::string& error) {
    error.clear();
    const Kind& kind = which == PluginKind::Test ? testKind : fixtureKind;
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
            // made with RTF 2.x's macros: its objects are made through its factory
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
    std::shared_ptr<PluginFactory> factory(new PluginFactory());
    factory->library_ = std::move(opened);
    factory->filename_ = filename;
    factory->what_ = kind.what;
    factory->create_ = create;
    factory->destroy_ = destroyer;
    return factory;
}

// The objects' code lives in the library: they must all be gone before it closes.
PluginFactory::~PluginFactory() = default;

void* PluginFactory::make(std::string& error) const {
    error.clear();
    void* object = nullptr;
    try {
        object = create_();
    } catch (const std::exception& e) {
        error = "the constructor of the " + std::string(what_) + " in '" + filename_ +
                "' threw: " + e.what();
        return nullptr;
    } catch (...) {
        error = "the constructor of the " + std::string(what_) + " in '" + filename_ +
                "' threw an exception";
        return nullptr;
    }
    if (object == nullptr) {
        error = "the factory of '" + filename_ + "' returned no object";
    }
    return object;
}

void PluginFactory::destroy(void* object) const {
    if (object != nullptr) {
        destroy_(object);
    }
}

}  // namespace plugin
}  // namespace robottestingframework
