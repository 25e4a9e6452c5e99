// Finding and loading the script language modules (see script_module_interface.h) on first use.
#pragma once

#include <string>

#include "languages/script_module_interface.h"

namespace robottestingframework {
namespace languages {

// The module of `language` ("python", "lua", "ruby"), loaded the first time it is asked for and
// kept for the life of the process. nullptr and `error` set (dlerror's words) when it cannot be
// loaded. Looked for in $RTF_LANGUAGE_DIR when set, else in the folder the program's libraries
// sit in (../lib/robottestingframework from the program), else where it was installed.
const LanguageModule* languageModule(const std::string& language, std::string& error);
// The platform's part of it (script_module_loading-posix.cpp: dlopen, -windows.cpp:
// LoadLibrary): finds and loads the module, every time it is called.
const LanguageModule* loadLanguageModule(const std::string& language, std::string& error);

// The script languages of this build ("python", "lua", "ruby"), each in a module of its own.
bool isScriptLanguage(const std::string& type);

// Why a test or fixture of `type` cannot run in this build, for an error after its file name:
// "this build does not support ruby", or what is missing on this platform.
std::string unsupportedTypeReason(const std::string& type);

}  // namespace languages
}  // namespace robottestingframework
