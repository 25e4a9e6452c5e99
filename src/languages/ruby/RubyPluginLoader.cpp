// The public RubyPluginLoader: the ruby module (robottestingframework-ruby.so) is
// loaded on the first open(), through the code the runner uses.
#include <robottestingframework/ruby/RubyPluginLoader.h>

#include "languages/script_test_loader.h"

namespace robottestingframework {
namespace plugin {

RubyPluginLoader::RubyPluginLoader()
    : implementation_(std::make_unique<ScriptTestLoader>("ruby")) {}

RubyPluginLoader::~RubyPluginLoader() = default;

TestCase* RubyPluginLoader::open(const std::string filename) {
    return implementation_->open(filename);
}

void RubyPluginLoader::close() {
    implementation_->close();
}

const std::string RubyPluginLoader::getLastError() {
    return implementation_->lastError();
}

}  // namespace plugin
}  // namespace robottestingframework
