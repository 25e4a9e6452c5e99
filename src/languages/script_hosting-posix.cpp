// Forking a worker through its language's module when the module forks itself (POSIX: the
// fork server's workers); see test_loader.h.
#include <unistd.h>

#include "languages/script_module_loading.h"
#include "languages/test_loader.h"

namespace robottestingframework {
namespace languages {

pid_t forkLanguage(const std::string& type) {
    std::string error;
    const LanguageModule* module = isScriptLanguage(type) ? languageModule(type, error) : nullptr;
    return module != nullptr && module->fork != nullptr ? module->fork() : ::fork();
}

}  // namespace languages
}  // namespace robottestingframework
