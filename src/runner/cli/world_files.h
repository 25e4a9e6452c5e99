// The world files of the suites' process fixtures, read when the plan is made: a world file
// that cannot be started (missing, malformed, a dependency cycle, an unknown process in
// `depends`, a bad value) is a configuration error before the run, for --list too, instead of
// a set-up failure found when the suite's turn comes.
#pragma once

#include <string>
#include <vector>

#include "runner/model/suite_model.h"
#include "runner/schedule/resources.h"

namespace robottestingframework {
namespace runner {

// A shared world's fixture (scope="run") gets every variable of its suite as --var, as any
// process fixture does; two suites sharing it would then be two worlds as soon as one of them
// defines a variable the world never reads. So each shared world keeps, of the --var words of
// its param, those whose ${NAME} its world file reads: its identity is what reaches it.
void keepSharedWorldVariables(std::vector<SuiteSpec>& suites);

// Empty when every world file reads; else the first problem, naming the world file and line
// (or the suite file and line of a fixture whose world file is missing). A ${resource.POOL}
// in a fixture's param is read as the pool's first items, as they are only given at run time.
std::string checkWorldFiles(const std::vector<SuiteSpec>& suites, const ResourcePools& pools);

}  // namespace runner
}  // namespace robottestingframework
