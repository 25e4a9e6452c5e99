// Checks, before anything runs, that each --output can be written without destroying
// something: not a folder, not a file the run reads (a suite file, a test, a fixture), not the
// file of another output. A run of an hour should not end on "cannot write the output".
#pragma once

#include <string>
#include <vector>

#include "runner/cli/options.h"
#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

// Empty when every output is fine; else "--output junit:F: F is ..." naming the output and
// what it would replace. Files are compared by what they are (device and inode), so
// "./r.xml", "r.xml" and a link to it are one file.
std::string checkOutputPaths(const std::vector<OutputRequest>& outputs,
                             const std::vector<SuiteSpec>& suites);

// Creates the missing folders of each output's path before the run, as pytest's --junitxml
// does (`-o junit:out/r.xml` makes out/). False with `error` naming the output and the folder
// when one cannot be made (a file of that name, no permission).
bool createOutputFolders(const std::vector<OutputRequest>& outputs, std::string& error);

// When an output (or --merge's) goes to the standard output ("-", /dev/stdout), keeps it for the
// reports and sends the console and every other line of the runner to the standard error, so a
// pipe (`--output json:- | jq`) reads the report alone. False with `error` set when the
// descriptors cannot be moved.
bool keepStandardOutputForReports(const Options& options, std::string& error);

}  // namespace runner
}  // namespace robottestingframework
