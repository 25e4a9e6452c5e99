#include "runner/cli/list_command.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "reporters/standard_output.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/listing.h"
#include "runner/cli/program_name.h"

namespace robottestingframework {
namespace runner {

int listCommand(const Options& options, PlannedRun& planned, const Overrides& overrides) {
    std::vector<SuiteSpec>& suites = planned.suites;
    for (auto& suite : suites) {
        applyOverrides(suite, overrides);
    }
    // The JSON list on the standard output is the list: the text one would only repeat it
    // (and the standard error is the console's then).
    const bool jsonToStandardOutput =
        options.list && std::any_of(options.outputs.begin(), options.outputs.end(),
                                    [](const OutputRequest& output) {
                                        return output.type == "json" &&
                                               reporters::namesStandardOutput(output.file);
                                    });
    if (!jsonToStandardOutput) {
        std::fputs((options.listVariables ? listVariablesText(suites)
                                          : listText(suites, planned.shardOf, planned.shard.count))
                       .c_str(),
                   stdout);
    }
    for (const auto& output : options.outputs) {
        std::string error;
        if (options.list && output.type == "json" &&
            !writeListJson(output.file, suites, error, planned.shardOf)) {
            std::fprintf(stderr, "%s: cannot write the list %s: %s\n", programName,
                         output.file.c_str(), error.c_str());
            return configurationError;
        }
    }
    return allPassed;
}

}  // namespace runner
}  // namespace robottestingframework
