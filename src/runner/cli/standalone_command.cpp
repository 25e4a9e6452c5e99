#include "runner/cli/standalone_command.h"

#include "runner/cli/exit_status.h"
#include "runner/cli/history_import_command.h"
#include "runner/cli/history_report_command.h"
#include "runner/cli/merge_command.h"
#include "runner/cli/world_keeper.h"

namespace robottestingframework {
namespace runner {

std::optional<int> standaloneCommand(const Options& options) {
    if (!options.merge.type.empty()) {
        return mergeCommand(options);
    }
    if (!options.historyImports.empty()) {
        const int status = historyImportCommand(options);
        if (status != allPassed || !options.historyReport) {
            return status;
        }
    }
    if (options.historyReport) {
        return historyReportCommand(options);
    }
    if (!options.worldDown.empty()) {
        return worldDownCommand(options);
    }
    return std::nullopt;
}

}  // namespace runner
}  // namespace robottestingframework
