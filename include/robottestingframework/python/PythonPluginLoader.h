// Loads a Python 3 test case file (RTF 2.x's plugin::PythonPluginLoader) so that a program can
// run it with its own TestRunner and TestResult, in its own process. Link
// RobotTestingFramework::RTF_python; the interpreter is loaded on the first open().
#pragma once

#include <memory>
#include <string>

#include <robottestingframework/PluginLoader.h>
#include <robottestingframework/TestCase.h>

namespace robottestingframework {
namespace plugin {

class ScriptTestLoader;

class PythonPluginLoader : public PluginLoader {
public:
    PythonPluginLoader();
    ~PythonPluginLoader() override;

    // The test case of `filename`, owned by the loader; it can be run several times.
    TestCase* open(const std::string filename) override;
    void close() override;
    const std::string getLastError() override;

private:
    std::unique_ptr<ScriptTestLoader> implementation_;
};

}  // namespace plugin
}  // namespace robottestingframework
