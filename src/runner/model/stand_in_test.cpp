#include "runner/model/stand_in_test.h"

#include <string>

namespace robottestingframework {
namespace runner {

PluginTest::PluginTest(const TestSpec& spec, TestExecutor& executor)
    : Test(displayName(spec)), spec_(spec), executor_(executor) {
    setKey(spec.id.empty() ? displayName(spec) : spec.id);
}

std::string PluginTest::displayName(const TestSpec& spec) {
    return (spec.name.empty() ? spec.plugin : spec.name).str();
}

void PluginTest::run(TestResult& result) {
    interrupted_ = false;
    unsigned int attempt = 1;
    for (;; ++attempt) {
        clearCriticalError();
        status_ = executor_.run(spec_, *this, result);
        ran_ = true;
        // An interrupted run retries nothing: the user asked it to stop.
        if (!isFailure(status_) || attempt > retries_ || interrupted_ ||
            status_ == TestStatus::Interrupted) {
            break;
        }
        result.retryTest(this, TestMessage("attempt " + std::to_string(attempt) + " of " +
                                           std::to_string(retries_ + 1) + " " + toString(status_) +
                                           "; running it again"));
    }
    if (status_ == TestStatus::Passed && attempt > 1) {
        status_ = TestStatus::Flaky;
    }
}

void PluginTest::interrupt() {
    interrupted_ = true;
    executor_.interrupt();
}

}  // namespace runner
}  // namespace robottestingframework
