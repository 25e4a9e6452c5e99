// --lf and --ff: the run cut down to, or reordered by, the last run's failures (their ids,
// "SUITE/TEST" as model/test_id.h makes them; cli/last_run_cache.h keeps them).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

// How many tests of `suites` have an id in `ids`.
std::size_t countTestsNamed(const std::vector<SuiteSpec>& suites, const std::set<std::string>& ids);

// --lf: keeps only the tests whose id is in `ids`, and the suites left with one (their fixtures
// run as usual); a test depending on one left out runs without it, as --rerun-failed's do.
void keepTestsNamed(std::vector<SuiteSpec>& suites, const std::set<std::string>& ids);

// --ff: the suites holding a test of `ids` first, then the others, each group in its order; in
// each suite, those tests first, unless a test of the suite depends on another (its order is
// then the suite file's, which its dependencies may rely on).
void putTestsNamedFirst(std::vector<SuiteSpec>& suites, const std::set<std::string>& ids);

}  // namespace runner
}  // namespace robottestingframework
