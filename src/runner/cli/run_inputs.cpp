#include "runner/cli/run_inputs.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "dll/library_naming.h"
#include "platform/environment.h"
#include "runner/cli/command_line_suites.h"
#include "runner/cli/output_paths.h"
#include "runner/cli/program_name.h"
#include "runner/cli/sharded_run_setup.h"
#include "runner/cli/world_files.h"
#include "runner/plan/run_gate.h"

namespace robottestingframework {
namespace runner {

namespace {

// --plugin-path DIR...: absolute, in front of RTF_PLUGIN_PATH, which every plug-in look-up
// reads (plugin::findPlugin), here and in the workers that inherit it.
bool usePluginPath(const std::vector<std::string>& folders) {
    if (folders.empty()) {
        return true;
    }
    std::string path;
    for (const auto& folder : folders) {
        std::error_code error;
        if (!std::filesystem::is_directory(folder, error)) {
            std::fprintf(stderr, "%s: --plugin-path %s: no such folder\n", programName,
                         folder.c_str());
            return false;
        }
        path += (path.empty() ? "" : std::string(1, plugin::pathListSeparator())) +
                std::filesystem::absolute(folder, error).lexically_normal().string();
    }
    const char* before = std::getenv("RTF_PLUGIN_PATH");
    if (before != nullptr && *before != '\0') {
        path += plugin::pathListSeparator() + std::string(before);
    }
    platform::setEnvironment("RTF_PLUGIN_PATH", path);
    return true;
}

void sayWarnings(const std::vector<std::string>& warnings) {
    for (const auto& warning : warnings) {
        std::fprintf(stderr, "%s\n", warning.c_str());
    }
}

}  // namespace

bool readRunInputs(Options& options, RunInputs& inputs) {
    if (!usePluginPath(options.pluginPath)) {
        return false;
    }
    std::vector<std::string> warnings;
    try {
        inputs.suites = readSources(options, warnings);
    } catch (const std::exception& e) {
        sayWarnings(warnings);
        std::fprintf(stderr, "%s: %s\n", programName, e.what());
        return false;
    }
    sayWarnings(warnings);
    // Once the suites have read ${env:...} and before anything starts: the CI engines' shard
    // variables are read, then taken out of the environment the tests inherit.
    std::string error;
    if (!prepareShard(options, inputs.shard, error)) {
        std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
        return false;
    }
    inputs.overrides = Overrides{options.param, options.environment, options.repetition,
                                 options.timeout, options.variables};
    for (const auto& warning : unreadVariables(inputs.suites, inputs.overrides)) {
        std::fprintf(stderr, "%s: %s\n", programName, warning.c_str());
    }
    for (const std::string& problem :
         {findUnknownDependency(inputs.suites), findDependencyCycle(inputs.suites),
          checkOutputPaths(options.outputs, inputs.suites)}) {
        if (!problem.empty()) {
            std::fprintf(stderr, "%s: %s\n", programName, problem.c_str());
            return false;
        }
    }
    if (!options.resources.empty()) {
        try {
            inputs.pools = readResourceFile(options.resources);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: --resources %s\n", programName, e.what());
            return false;
        }
    }
    std::string poolProblem = addSuiteDefaults(inputs.suites, inputs.pools);
    if (poolProblem.empty()) {
        poolProblem = checkPools(inputs.suites, inputs.pools);
    }
    if (!poolProblem.empty()) {
        std::fprintf(stderr, "%s: %s\n", programName, poolProblem.c_str());
        return false;
    }
    keepSharedWorldVariables(inputs.suites);
    const std::string worldProblem = checkWorldFiles(inputs.suites, inputs.pools);
    if (!worldProblem.empty()) {
        std::fprintf(stderr, "%s: %s\n", programName, worldProblem.c_str());
        return false;
    }
    // Last, once every input is known good: no folder is made for a run that never starts.
    if (!createOutputFolders(options.outputs, error)) {
        std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
        return false;
    }
    return true;
}

}  // namespace runner
}  // namespace robottestingframework
