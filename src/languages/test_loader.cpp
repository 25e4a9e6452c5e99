#include "languages/test_loader.h"

#include <algorithm>

#include "languages/executable_file.h"
#include "languages/language_loaders.h"
#include "languages/script_module_loading.h"

namespace robottestingframework {
namespace languages {

namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() &&
           std::equal(suffix.rbegin(), suffix.rend(), text.rbegin());
}

std::string extensionType(const std::string& path) {
    // A versioned library (libfoo.so.1) is still a library.
    if (endsWith(path, ".so") || path.find(".so.") != std::string::npos ||
        endsWith(path, ".dylib") || endsWith(path, ".dll")) {
        return "dll";
    }
    if (endsWith(path, ".py")) {
        return "python";
    }
    if (endsWith(path, ".lua")) {
        return "lua";
    }
    if (endsWith(path, ".rb")) {
        return "ruby";
    }
    return {};
}

// "Python" for "python": how errors name a language.
std::string languageName(const std::string& type) {
    std::string name = type;
    if (!name.empty()) {
        name[0] = static_cast<char>(name[0] - 'a' + 'A');
    }
    return name;
}

}  // namespace

bool isScriptLanguage([[maybe_unused]] const std::string& type) {  // unused without languages
#ifdef RTF_HAVE_PYTHON
    if (type == "python") {
        return true;
    }
#endif
#ifdef RTF_HAVE_LUA
    if (type == "lua") {
        return true;
    }
#endif
#ifdef RTF_HAVE_RUBY
    if (type == "ruby") {
        return true;
    }
#endif
    return false;
}

namespace {

const LanguageModule* scriptModule(const std::string& type, std::string& error) {
    std::string reason;
    const LanguageModule* module = languageModule(type, reason);
    if (module == nullptr) {
        error = languageName(type) + " test cases are not available: " + reason;
    }
    return module;
}

}  // namespace

std::string typeFromFile(const std::string& path) {
    std::string type = extensionType(path);
    if (!type.empty()) {
        return type;
    }
    if (isExecutableFile(path)) {
        return "exec";
    }
    return {};
}

bool isSupportedType(const std::string& type) {
    if (type == "dll" || type == "exec" || type == "process") {
        return true;  // "process": fixtures only (a world file)
    }
    return isScriptLanguage(type);
}

std::unique_ptr<LoadedTest> loadTest(const std::string& type, const std::string& path,
                                     std::string& error) {
    if (type == "dll") {
        return loadDllTest(path, error);
    }
    if (type == "exec") {
        return loadExecTest(path, error);
    }
    if (isScriptLanguage(type)) {
        const LanguageModule* module = scriptModule(type, error);
        return module != nullptr ? module->loadTest(path, error) : nullptr;
    }
    error = "test type '" + type + "' is not supported by this build";
    return nullptr;
}

bool prestartLanguage(const std::string& type, std::string& error) {
    if (!isScriptLanguage(type)) {
        error = "not a script language";
        return false;
    }
    const LanguageModule* module = scriptModule(type, error);
    if (module == nullptr) {
        return false;
    }
    if (module->prestart == nullptr) {
        error = "its module cannot pre-start it";
        return false;
    }
    return module->prestart(error);
}

void rehearseLanguage(const std::string& type) {
    std::string error;
    const LanguageModule* module = isScriptLanguage(type) ? languageModule(type, error) : nullptr;
    if (module != nullptr && module->rehearse != nullptr) {
        module->rehearse();
    }
}

int hostLanguage(const std::string& type, int (*serve)(void*), void* context, bool& hosted) {
    std::string error;
    const LanguageModule* module = isScriptLanguage(type) ? languageModule(type, error) : nullptr;
    hosted = module != nullptr && module->host != nullptr;
    return hosted ? module->host(serve, context) : serve(context);
}

std::unique_ptr<LoadedFixture> loadFixture(const std::string& type, const std::string& path,
                                           std::string& error) {
    if (type == "dll") {
        return loadDllFixture(path, error);
    }
    if (type == "process") {
        return loadProcessFixture(path, error);
    }
    if (isScriptLanguage(type)) {
        const LanguageModule* module = scriptModule(type, error);
        if (module == nullptr) {
            return nullptr;
        }
        if (module->loadFixture != nullptr) {
            return module->loadFixture(path, error);
        }
    }
    error = "fixture type '" + type + "' is not supported by this build";
    return nullptr;
}

}  // namespace languages
}  // namespace robottestingframework
