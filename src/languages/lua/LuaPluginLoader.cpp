// The public LuaPluginLoader: the lua module (robottestingframework-lua.so) is
// loaded on the first open(), through the code the runner uses.
#include <robottestingframework/lua/LuaPluginLoader.h>

#include "languages/script_test_loader.h"

namespace robottestingframework {
namespace plugin {

LuaPluginLoader::LuaPluginLoader() : implementation_(std::make_unique<ScriptTestLoader>("lua")) {}

LuaPluginLoader::~LuaPluginLoader() = default;

TestCase* LuaPluginLoader::open(const std::string filename) {
    return implementation_->open(filename);
}

void LuaPluginLoader::close() {
    implementation_->close();
}

const std::string LuaPluginLoader::getLastError() {
    return implementation_->lastError();
}

}  // namespace plugin
}  // namespace robottestingframework
