#include "languages/plugin_locator.h"

#include <robottestingframework/dll/DllPluginLoader.h>

#include "languages/script_module_loading.h"
#include "languages/test_loader.h"

namespace robottestingframework {
namespace languages {

namespace {

std::string folderOf(const std::string& file) {
    std::size_t slash = file.rfind('/');
    if (file.empty() || slash == std::string::npos) {
        return ".";
    }
    return slash == 0 ? "/" : file.substr(0, slash);
}

}  // namespace

bool locatePlugin(const std::string& plugin, const std::string& givenPath,
                  const std::string& givenType, const std::string& suiteFile, std::string& path,
                  std::string& type, std::string& error) {
    path = givenPath;
    if (path.empty()) {
        std::string searched;
        path = plugin::findPlugin(plugin, folderOf(suiteFile), &searched);
        if (path.empty()) {
            error = "'" + plugin + "' " + searched;
            return false;
        }
    }
    type = givenType.empty() ? typeFromFile(path) : givenType;
    if (type.empty()) {
        error = "cannot tell what kind of plug-in '" + path +
                "' is (not a .so, .py, .lua or .rb file, nor an executable); give its type, "
                "e.g. type=\"dll\"";
        return false;
    }
    if (!isSupportedType(type)) {
        error = "'" + path + "' is a " + type + " plug-in; " + unsupportedTypeReason(type);
        return false;
    }
    return true;
}

}  // namespace languages
}  // namespace robottestingframework
