// Windows: an isolated run's fixtures run in the runner's process, as with --isolation none
// (docs/development/platforms.md); its tests still run in workers. A fixture worker needs the
// fixture calls over a second pipe, not built yet.
#include "runner/execution/in_process_executor.h"
#include "runner/execution/isolated_executor.h"

namespace robottestingframework {
namespace isolation {

std::unique_ptr<FixtureManager> IsolatedExecutor::makeFixture(const runner::FixtureSpec& spec,
                                                              std::string& error) {
    // The in-process fixture manager owns what it loaded: the executor that made it may go.
    runner::InProcessExecutor inProcess;
    return inProcess.makeFixture(spec, error);
}

}  // namespace isolation
}  // namespace robottestingframework
