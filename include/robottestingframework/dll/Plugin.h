// Makes a shared library a test or fixture plug-in the runner can load:
//   class MyTest : public robottestingframework::TestCase { ... };
//   ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(MyTest)
// The library exports a factory the runner finds by name; the class needs a default constructor.
// It also exports RTF 2.x's SHLIBPP factory (robottestingframework_dll_factory or
// robottestingframework_fixture_factory), so programs that load plug-ins with shlibpp's
// SharedLibraryClassFactory, as RTF 2.x's did, load these too.
#pragma once

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/SharedLibraryClass.h>  // as RTF 2.x's Plugin.h did

// The factories' names in RTF 2.x's plug-ins (its macros expand to SHLIBPP factories).
#define ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME "robottestingframework_dll_factory"
#define ROBOTTESTINGFRAMEWORK_FIXTURE_FACTORY_NAME "robottestingframework_fixture_factory"

#if defined(_WIN32)
#define ROBOTTESTINGFRAMEWORK_PLUGIN_EXPORT __declspec(dllexport)
#else
#define ROBOTTESTINGFRAMEWORK_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

// Bumped when the factory's contract changes; the loader refuses other versions.
#define ROBOTTESTINGFRAMEWORK_PLUGIN_ABI 1

#define ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(classname)                                        \
    extern "C" ROBOTTESTINGFRAMEWORK_PLUGIN_EXPORT int robottestingframework_plugin_abi() {    \
        return ROBOTTESTINGFRAMEWORK_PLUGIN_ABI;                                               \
    }                                                                                          \
    extern "C" ROBOTTESTINGFRAMEWORK_PLUGIN_EXPORT void* robottestingframework_create_test() { \
        return static_cast<::robottestingframework::TestCase*>(new classname());               \
    }                                                                                          \
    extern "C" ROBOTTESTINGFRAMEWORK_PLUGIN_EXPORT void robottestingframework_destroy_test(    \
        void* object) {                                                                        \
        delete static_cast<::robottestingframework::TestCase*>(object);                        \
    }                                                                                          \
    SHLIBPP_DEFINE_SHARED_SUBCLASS(robottestingframework_dll_factory, classname,               \
                                   ::robottestingframework::TestCase)

#define ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(classname)                                   \
    extern "C" ROBOTTESTINGFRAMEWORK_PLUGIN_EXPORT int robottestingframework_plugin_abi() {       \
        return ROBOTTESTINGFRAMEWORK_PLUGIN_ABI;                                                  \
    }                                                                                             \
    extern "C" ROBOTTESTINGFRAMEWORK_PLUGIN_EXPORT void* robottestingframework_create_fixture() { \
        return static_cast<::robottestingframework::FixtureManager*>(new classname());            \
    }                                                                                             \
    extern "C" ROBOTTESTINGFRAMEWORK_PLUGIN_EXPORT void robottestingframework_destroy_fixture(    \
        void* object) {                                                                           \
        delete static_cast<::robottestingframework::FixtureManager*>(object);                     \
    }                                                                                             \
    SHLIBPP_DEFINE_SHARED_SUBCLASS(robottestingframework_fixture_factory, classname,              \
                                   ::robottestingframework::FixtureManager)
