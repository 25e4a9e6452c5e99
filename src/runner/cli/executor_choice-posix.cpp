#include "runner/cli/executor_choice.h"

#include "runner/execution/isolated_executor.h"

namespace robottestingframework {
namespace runner {

std::unique_ptr<TestExecutor> chooseExecutor(Options& options, std::string& error) {
    if (options.isolation == Isolation::None) {
        return inProcessExecutor(options);
    }
    isolation::IsolationOptions isolationOptions;
    isolationOptions.verbose = options.verbose;
    auto isolated = std::make_unique<isolation::IsolatedExecutor>(isolationOptions);
    if (!isolated->start(error)) {
        return nullptr;
    }
    return isolated;
}

}  // namespace runner
}  // namespace robottestingframework
