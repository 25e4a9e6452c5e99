// What PythonPluginLoader, LuaPluginLoader and RubyPluginLoader share: a script test loaded
// through its language's module (script_module_interface.h), kept until closed.
#pragma once

#include <memory>
#include <string>

#include <robottestingframework/TestCase.h>

#include "languages/test_loader.h"

namespace robottestingframework {
namespace plugin {

class ScriptTestLoader {
public:
    // `language`: "python", "lua" or "ruby", as the modules are named.
    explicit ScriptTestLoader(std::string language);
    ~ScriptTestLoader();

    // nullptr and lastError() set (naming the file) when the file is missing, is another
    // language's, or the language refuses it (its own message, with the line).
    TestCase* open(const std::string& filename);
    void close();
    const std::string& lastError() const { return error_; }

private:
    std::string language_;
    std::unique_ptr<languages::LoadedTest> loaded_;
    std::string error_;
};

}  // namespace plugin
}  // namespace robottestingframework
