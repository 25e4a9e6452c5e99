// Windows: no script language is built (README: Platforms). Python and Ruby need a Windows
// CPython or Ruby to link and test with, which these machines do not have.
#include "languages/script_module_loading.h"

namespace robottestingframework {
namespace languages {

const LanguageModule* languageModule(const std::string& language, std::string& error) {
    error = language + " test cases are not built for Windows";
    return nullptr;
}

std::string unsupportedTypeReason(const std::string& type) {
    if (type == "python" || type == "ruby") {
        return std::string(type == "python" ? "Python" : "Ruby") +
               " tests are not built for Windows (no Windows " +
               (type == "python" ? "CPython" : "Ruby") + " to build them with)";
    }
    return type + " tests are not built for Windows yet";
}

}  // namespace languages
}  // namespace robottestingframework
