#include "languages/script_test_loader.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <utility>

#include "languages/script_module_loading.h"

namespace robottestingframework {
namespace plugin {

namespace {

// The language a file's extension says it is in ("" when it says nothing we know).
std::string languageOf(const std::string& path) {
    static const std::pair<const char*, const char*> extensions[] = {
        {".py", "python"}, {".lua", "lua"}, {".rb", "ruby"}, {".so", "C++"}};
    std::string::size_type dot = path.find_last_of('.');
    std::string::size_type slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
        return {};
    }
    std::string extension = path.substr(dot);
    for (const auto& [suffix, language] : extensions) {
        if (extension == suffix) {
            return language;
        }
    }
    return {};
}

std::string title(std::string language) {
    if (!language.empty() && language[0] >= 'a' && language[0] <= 'z') {
        language[0] = static_cast<char>(language[0] - 'a' + 'A');
    }
    return language;
}

}  // namespace

ScriptTestLoader::ScriptTestLoader(std::string language) : language_(std::move(language)) {}

ScriptTestLoader::~ScriptTestLoader() {
    close();
}

TestCase* ScriptTestLoader::open(const std::string& filename) {
    close();
    error_.clear();
    struct stat info {};
    if (::stat(filename.c_str(), &info) != 0) {
        error_ = "cannot open '" + filename + "': " + std::strerror(errno);
        return nullptr;
    }
    if (!S_ISREG(info.st_mode) || !std::ifstream(filename)) {
        error_ = "cannot read '" + filename + "': not a readable file";
        return nullptr;
    }
    std::string language = languageOf(filename);
    if (!language.empty() && language != language_) {
        error_ = "'" + filename + "' is a " + title(language) + " file, not a " + title(language_) +
                 " test";
        return nullptr;
    }
    std::string reason;
    const languages::LanguageModule* module = languages::languageModule(language_, reason);
    if (module == nullptr) {
        error_ = "cannot load '" + filename + "': " + title(language_) +
                 " test cases are not available: " + reason;
        return nullptr;
    }
    loaded_ = module->loadTest(filename, reason);
    if (!loaded_ || loaded_->get() == nullptr) {
        loaded_.reset();
        // The language's own words; they name the file when they say where the error is.
        error_ = reason.find(filename) == std::string::npos
                     ? "cannot load '" + filename + "': " + reason
                     : reason;
        return nullptr;
    }
    return loaded_->get();
}

void ScriptTestLoader::close() {
    loaded_.reset();
}

}  // namespace plugin
}  // namespace robottestingframework
