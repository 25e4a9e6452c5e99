#include "languages/script_module_loading.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "platform/process.h"

#ifndef RTF_LANGUAGE_RELATIVE_DIR
#define RTF_LANGUAGE_RELATIVE_DIR "../lib/robottestingframework"
#endif
#ifndef RTF_LANGUAGE_INSTALL_DIR
#define RTF_LANGUAGE_INSTALL_DIR ""
#endif

namespace robottestingframework {
namespace languages {

namespace {

// The folder of the shared library this code is linked into (libRobotTestingFrameworkLua.so
// & co, see PluginLoader.h), or empty when it is linked into the program itself.
std::string libraryFolder(const std::string& program) {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&libraryFolder), &info) == 0 ||
        info.dli_fname == nullptr) {
        return {};
    }
    std::error_code error;
    std::filesystem::path library = std::filesystem::canonical(info.dli_fname, error);
    if (error || library == std::filesystem::canonical(program, error)) {
        return {};
    }
    return library.parent_path().string();
}

std::vector<std::string> moduleFolders() {
    if (const char* override = std::getenv("RTF_LANGUAGE_DIR")) {
        if (*override != '\0') {
            return {override};
        }
    }
    std::vector<std::string> folders;
    std::string self = platform::executablePath();
    // A program using a plug-in loader library may live anywhere: the modules are beside the
    // library (lib/robottestingframework/ next to lib/libRobotTestingFrameworkLua.so).
    std::string library = libraryFolder(self);
    if (!library.empty()) {
        folders.push_back(library + "/robottestingframework");
    }
    if (!self.empty()) {
        folders.push_back(self.substr(0, self.find_last_of('/')) + "/" + RTF_LANGUAGE_RELATIVE_DIR);
    }
    if (*RTF_LANGUAGE_INSTALL_DIR != '\0') {
        folders.emplace_back(RTF_LANGUAGE_INSTALL_DIR);
    }
    return folders;
}

}  // namespace

const LanguageModule* loadLanguageModule(const std::string& language, std::string& error) {
    std::string file = "robottestingframework-" + language + ".so";
    std::vector<std::string> folders = moduleFolders();
    // The first folder that has the file; when none has it, the first one, so that dlerror
    // says which file is missing.
    std::string path = folders.empty() ? file : folders.front() + "/" + file;
    for (const std::string& folder : folders) {
        if (::access((folder + "/" + file).c_str(), F_OK) == 0) {
            path = folder + "/" + file;
            break;
        }
    }
    // RTLD_GLOBAL: the interpreters' own extension modules (Python's _json, Ruby's gems) expect
    // the interpreter's symbols to be global, as when it is linked into the program.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle == nullptr) {
        const char* reason = ::dlerror();
        error = reason != nullptr ? reason : path + ": cannot be loaded";
        return nullptr;
    }
    using Entry = const LanguageModule* (*)();
    auto entry = reinterpret_cast<Entry>(::dlsym(handle, RTF_LANGUAGE_MODULE_ENTRY));
    if (entry == nullptr) {
        const char* reason = ::dlerror();
        error = reason != nullptr ? reason : path + ": no " RTF_LANGUAGE_MODULE_ENTRY;
        ::dlclose(handle);
        return nullptr;
    }
    const LanguageModule* module = entry();
    if (module == nullptr || module->version != kLanguageModuleVersion ||
        module->loadTest == nullptr) {
        error = path + ": built for another version of the framework";
        ::dlclose(handle);
        return nullptr;
    }
    return module;  // never closed: its objects and interpreter live until the process ends
}

std::string unsupportedTypeReason(const std::string& type) {
    return "this build does not support " + type;
}

}  // namespace languages
}  // namespace robottestingframework
