// One loader per language; test_loader.cpp picks among them. Each lives in its own folder.
#pragma once

#include <memory>
#include <string>

#include "languages/test_loader.h"

namespace robottestingframework {
namespace languages {

// dll/: C++ plug-ins (ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN).
std::unique_ptr<LoadedTest> loadDllTest(const std::string& path, std::string& error);
std::unique_ptr<LoadedFixture> loadDllFixture(const std::string& path, std::string& error);

// src/fixtures/process/: the built-in process fixture; `path` is its world file.
std::unique_ptr<LoadedFixture> loadProcessFixture(const std::string& path, std::string& error);

// exec/: any executable; TAP on its stdout becomes checks.
std::unique_ptr<LoadedTest> loadExecTest(const std::string& path, std::string& error);

// python/, lua/, ruby/: each built into a module of its own (script_module_interface.h), which
// test_loader.cpp loads on first use; not part of rtf_languages.
std::unique_ptr<LoadedTest> loadPythonTest(const std::string& path, std::string& error);
std::unique_ptr<LoadedFixture> loadPythonFixture(const std::string& path, std::string& error);
std::unique_ptr<LoadedTest> loadLuaTest(const std::string& path, std::string& error);
std::unique_ptr<LoadedTest> loadRubyTest(const std::string& path, std::string& error);

}  // namespace languages
}  // namespace robottestingframework
