// Everything the command line asks to run, read into the model: the --suite files, the suites
// in the --suites folders, and the --test files and --tests folders as one more suite.
#pragma once

#include <string>
#include <vector>

#include "runner/cli/options.h"
#include "runner/model/suite_model.h"
#include "variables/variables.h"

namespace robottestingframework {
namespace runner {

// The name of the suite holding the tests given with --test and --tests.
extern const char* const commandLineSuiteName;

// Throws std::runtime_error (SuiteFileError for a suite file) on a configuration error: a
// folder that is not one, an unreadable or malformed suite. Remarks go to `warnings`.
std::vector<SuiteSpec> readSources(const Options& options, std::vector<std::string>& warnings);

// --var-file (in order: a later file wins) then --var. Throws std::runtime_error naming the
// file and line of a bad --var-file.
std::vector<variables::Variable> commandLineVariables(const Options& options);

// Files of `folder` (and its sub-folders when `recursive`) that `keep` accepts, sorted.
std::vector<std::string> listFolder(const std::string& folder, bool recursive,
                                    bool (*keep)(const std::string& path));

}  // namespace runner
}  // namespace robottestingframework
