// Suites of one run that start the same world (process fixtures naming one world file, or world
// files that give one name) would write their processes' logs into one folder, each suite's
// attachment mixing both worlds' lines. Each such suite's world gets its own instance name, and
// with it its own log folder.
#pragma once

#include <vector>

#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

// Adds `--instance NAME` to the param of each process fixture whose world (by its name, <world
// name="..."> or the file's stem) another suite of `suites` starts too (a shared world,
// scope="run", is one instance: it keeps its param): NAME is the suite's name, with "-2", "-3", ...
// on the second and later suites of one name. The fixture then writes its logs to <logdir>/<NAME>/.
// A world that one suite alone starts keeps <logdir>/ as it is.
void separateWorldLogs(std::vector<SuiteSpec>& suites);

}  // namespace runner
}  // namespace robottestingframework
