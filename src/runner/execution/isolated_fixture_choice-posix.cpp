// POSIX: an isolated run's fixtures run in a worker of their own, forked by the fork server.
#include "runner/execution/isolated_executor.h"

#include "languages/plugin_locator.h"
#include "runner/execution/isolated_fixture.h"

namespace robottestingframework {
namespace isolation {

std::unique_ptr<FixtureManager> IsolatedExecutor::makeFixture(const runner::FixtureSpec& spec,
                                                              std::string& error) {
    WorkRequest request;
    request.role = WorkRequest::Role::Fixture;
    request.param = spec.param;
    request.name = spec.plugin;
    if (!languages::locatePlugin(spec.plugin, spec.path, spec.type, spec.where.file, request.path,
                                 request.type, error)) {
        return nullptr;
    }
    if (!start(error)) {
        return nullptr;
    }
    return std::unique_ptr<FixtureManager>(new IsolatedFixture(server_, request, options_));
}

}  // namespace isolation
}  // namespace robottestingframework
