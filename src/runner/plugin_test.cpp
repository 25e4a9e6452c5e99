#include "plugin_test.h"

namespace robottestingframework {
namespace runner {

PluginTest::PluginTest(const TestSpec& spec, TestExecutor& executor)
    : Test(displayName(spec)), spec_(spec), executor_(executor) {}

std::string PluginTest::displayName(const TestSpec& spec) {
    return spec.name.empty() ? spec.plugin : spec.name;
}

void PluginTest::run(TestResult& result) {
    clearCriticalError();
    status_ = executor_.run(spec_, *this, result);
    ran_ = true;
}

void PluginTest::interrupt() {
    executor_.interrupt();
}

}  // namespace runner
}  // namespace robottestingframework
