// What a script language module (robottestingframework-<language>.so, built from python/, lua/,
// ruby/) gives to test_loader.cpp: its loaders, through one extern "C" entry point. Keeping the
// interpreters in modules loaded on first use means the runner and the workers it forks do not
// carry libpython, libruby and liblua unless a test needs them.
#pragma once

#include <memory>
#include <string>

#include "test_loader.h"

namespace robottestingframework {
namespace languages {

using TestLoaderFunction = std::unique_ptr<LoadedTest> (*)(const std::string& path,
                                                           std::string& error);
using FixtureLoaderFunction = std::unique_ptr<LoadedFixture> (*)(const std::string& path,
                                                                 std::string& error);

// Changes whenever LanguageModule or Loaded<> changes: a module built for another layout is
// refused instead of crashing.
constexpr int kLanguageModuleVersion = 1;

struct LanguageModule {
    int version;
    TestLoaderFunction loadTest;
    FixtureLoaderFunction loadFixture;  // nullptr: the language has no fixture managers
};

}  // namespace languages
}  // namespace robottestingframework

// The entry point every module defines (and the only symbol test_loader looks up).
#define RTF_LANGUAGE_MODULE_ENTRY "rtf_language_module"
extern "C" __attribute__((visibility("default")))
const robottestingframework::languages::LanguageModule*
rtf_language_module();
