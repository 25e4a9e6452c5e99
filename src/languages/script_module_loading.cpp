// The script language modules, each loaded once for the life of the process; loading one is
// the platform's (script_module_loading-posix.cpp, -windows.cpp).
#include "languages/script_module_loading.h"

#include <map>
#include <mutex>

namespace robottestingframework {
namespace languages {

const LanguageModule* languageModule(const std::string& language, std::string& error) {
    static std::mutex mutex;
    static std::map<std::string, const LanguageModule*> loaded;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = loaded.find(language);
    if (found != loaded.end()) {
        return found->second;
    }
    const LanguageModule* module = loadLanguageModule(language, error);
    if (module != nullptr) {
        loaded.emplace(language, module);
    }
    return module;
}

}  // namespace languages
}  // namespace robottestingframework
