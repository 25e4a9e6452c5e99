#include "runner/cli/merge_command.h"

#include <cstdio>
#include <exception>
#include <string>

#include "reporters/atomic_file.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/program_name.h"
#include "runner/reports/merge_reports.h"

namespace robottestingframework {
namespace runner {

int mergeCommand(const Options& options) {
    MergeRequest request{options.merge.type, options.merge.file, options.mergeReports,
                         options.expectShards};
    std::string error;
    try {
        if (reporters::writeFileAtomically(request.file, mergeReports(request), error)) {
            std::fprintf(stdout, "%s: merged %zu reports into %s\n", programName,
                         request.reports.size(), request.file.c_str());
            return allPassed;
        }
        error = "cannot write " + request.file + ": " + error;
    } catch (const std::exception& e) {
        error = e.what();
    }
    std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
    return configurationError;
}

}  // namespace runner
}  // namespace robottestingframework
