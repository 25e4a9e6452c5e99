// What a script language module (robottestingframework-<language>.so, built from python/, lua/,
// ruby/) gives to test_loader.cpp: its loaders, through one extern "C" entry point. Keeping the
// interpreters in modules loaded on first use means the runner and the workers it forks do not
// carry libpython, libruby and liblua unless a test needs them.
#pragma once

#include <sys/types.h>

#include <memory>
#include <string>

#include "languages/test_loader.h"

namespace robottestingframework {
namespace languages {

using TestLoaderFunction = std::unique_ptr<LoadedTest> (*)(const std::string& path,
                                                           std::string& error);
using FixtureLoaderFunction = std::unique_ptr<LoadedFixture> (*)(const std::string& path,
                                                                 std::string& error);
// Starts the runtime in a process that will fork a worker per test (the fork server's
// pre-started interpreter). False with `error` when it cannot be made safe to fork.
using PrestartFunction = bool (*)(std::string& error);
// fork() as the runtime needs it done once prestart() succeeded (its own before/after hooks).
using ForkFunction = pid_t (*)();
// Runs `serve(context)` on the thread that may call the runtime and fork it, and returns what
// it returned (a runtime that must be called from one thread of its own).
using HostFunction = int (*)(int (*serve)(void*), void* context);
// In a fork waiting for its test (a spare): does what a test does first, on a script of
// nothing, so that the pages a test touches are copied before the test, not during it.
using RehearseFunction = void (*)();

// Changes whenever LanguageModule or Loaded<> changes: a module built for another layout is
// refused instead of crashing.
constexpr int kLanguageModuleVersion = 3;

struct LanguageModule {
    int version;
    TestLoaderFunction loadTest;
    FixtureLoaderFunction loadFixture;  // nullptr: the language has no fixture managers
    PrestartFunction prestart;          // nullptr: every worker starts the runtime itself
    ForkFunction fork;                  // nullptr: plain fork()
    HostFunction host;                  // nullptr: any thread (the process's only one)
    RehearseFunction rehearse;          // nullptr: nothing to do ahead of a test
};

}  // namespace languages
}  // namespace robottestingframework

// The entry point every module defines (and the only symbol test_loader looks up): exported
// from the module's DLL on Windows, visible from its shared object elsewhere.
#define RTF_LANGUAGE_MODULE_ENTRY "rtf_language_module"
#ifdef _WIN32
#define RTF_LANGUAGE_MODULE_EXPORT __declspec(dllexport)
#else
#define RTF_LANGUAGE_MODULE_EXPORT __attribute__((visibility("default")))
#endif
extern "C" RTF_LANGUAGE_MODULE_EXPORT const robottestingframework::languages::LanguageModule*
rtf_language_module();
