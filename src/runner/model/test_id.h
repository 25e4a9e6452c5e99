// A test's id (docs/reference/test-ids.md): the one name every output, --filter, --list,
// --rerun-failed,
// --durations-from and --merge use for it. Made from the suite file alone, so it is the same on
// every machine and in every workspace: "SUITE/LOCAL", where LOCAL is the test's name="..." if the
// suite gives one, else its plug-in as written, normalised and relative to the suite's folder, then
// "[param]" when the same plug-in appears more than once with different params, then "[2]",
// "[3]", ... for a test that would otherwise share its id with an earlier one. A repetition k of
// a test is "ID#k". The name a test gives itself (setName) is only shown beside it.
#pragma once

#include <string>
#include <vector>

#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

// The plug-in part of an id: `plugin` as written (variables expanded) made lexically normal
// ("a/./b/../c" is "a/c"); a relative path beside the suite's folder is said from the folder both
// share ("../tests/x.py" is "tests/x.py": no id holds ".."); an absolute path is made relative to
// `suiteFolder` when below it, else only its file name is kept (a build tree's path must not
// reach the id).
std::string pluginIdPart(const std::string& plugin, const std::string& suiteFolder);

// A param on one line, as an id must be: runs of white space become one space, none at the ends.
std::string oneLine(const std::string& text);

// Gives each test of `suite` its LOCAL id (TestSpec::id), in document order. `suiteFolder` is the
// folder the suite's relative plug-in paths start from.
void assignTestIds(SuiteSpec& suite, const std::string& suiteFolder);

// "SUITE/LOCAL".
std::string testId(const SuiteSpec& suite, const TestSpec& test);

// Makes the ids of a run's tests unique across its suites. Where tests of two suite files would
// share an id (two files both <suite name="arm"> with the test t.py; suite "a" with the test
// "b/c" beside suite "a/b" with the test "c"), each of those suites' names is qualified by its
// file's path relative to the folder the colliding files share: "arm[left/arm.xml]/t.py" and
// "arm[right/arm.xml]/t.py". One suite file given several times (two copies side by side) has its
// later copies numbered: "robot/JointStatesTest", "robot[2]/JointStatesTest". Returns "" when
// every id is then unique; else an error naming the id and both tests' files and lines.
std::string makeIdsUniqueAcrossSuites(std::vector<SuiteSpec>& suites);

}  // namespace runner
}  // namespace robottestingframework
