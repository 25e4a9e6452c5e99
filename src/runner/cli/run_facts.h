// What a run was, for the reports that show it (the HTML report's run metadata): the command
// line, the variables given, the host, the working folder, the version, isolation and jobs.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "reporters/reporter.h"
#include "runner/cli/options.h"
#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

std::vector<std::pair<std::string, std::string>> runFacts(const Options& options);
// Adds the facts of each of `suite`'s tests (type, plug-in, param, tags) under "SUITE/id".
void addTestFacts(const SuiteSpec& suite, std::map<std::string, reporters::TestFacts>& facts);

}  // namespace runner
}  // namespace robottestingframework
