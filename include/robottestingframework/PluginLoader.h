// What every test-case loader offers (RTF 2.x's plugin::PluginLoader): open a file, get its
// TestCase, run it with your own TestRunner and TestResult, close. One loader per language:
// dll/DllPluginLoader.h, python/PythonPluginLoader.h, lua/LuaPluginLoader.h,
// ruby/RubyPluginLoader.h.
#pragma once

#include <string>

#include <robottestingframework/TestCase.h>

namespace robottestingframework {
namespace plugin {

class PluginLoader {
public:
    PluginLoader() = default;
    virtual ~PluginLoader() = default;
    PluginLoader(const PluginLoader&) = delete;
    PluginLoader& operator=(const PluginLoader&) = delete;

    // Loads `filename` and makes its test case, owned by the loader (valid until close(), the
    // next open() or the loader's end). nullptr on failure: getLastError() says which file and
    // why, and nothing is printed.
    virtual TestCase* open(const std::string filename) = 0;
    // Deletes the test case and lets its file go.
    virtual void close() = 0;
    // Why the last open() failed; empty after a success.
    virtual const std::string getLastError() = 0;
};

}  // namespace plugin
}  // namespace robottestingframework
