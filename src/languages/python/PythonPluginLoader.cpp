// The public PythonPluginLoader: the python module (robottestingframework-python.so) is
// loaded on the first open(), through the code the runner uses.
#include <robottestingframework/python/PythonPluginLoader.h>

#include "languages/script_test_loader.h"

namespace robottestingframework {
namespace plugin {

PythonPluginLoader::PythonPluginLoader()
    : implementation_(std::make_unique<ScriptTestLoader>("python")) {}

PythonPluginLoader::~PythonPluginLoader() = default;

TestCase* PythonPluginLoader::open(const std::string filename) {
    return implementation_->open(filename);
}

void PythonPluginLoader::close() {
    implementation_->close();
}

const std::string PythonPluginLoader::getLastError() {
    return implementation_->lastError();
}

}  // namespace plugin
}  // namespace robottestingframework
