// --rerun-failed REPORT: which tests an earlier JUnit or JSON (CTRF) output of this runner says
// failed, errored, crashed or timed out, and the suites cut down to them.
#pragma once

#include <string>
#include <vector>

#include "runner/model/suite_model.h"
#include "runner/reports/report_reader.h"

namespace robottestingframework {
namespace runner {

struct FailedTest {
    std::string suite;  // as the report names it; empty for tests run outside a suite
    std::string test;
};

// The tests `report` says failed, errored, crashed or timed out.
std::vector<FailedTest> failedTests(const Report& report);

// The failed tests of `path`. Throws std::runtime_error saying why when the file is missing,
// unreadable, not JUnit or JSON, or not written by this runner.
std::vector<FailedTest> readFailedTests(const std::string& path);
// The same from the report's text (`path` names it in messages).
std::vector<FailedTest> parseFailedTests(const std::string& text, const std::string& path);

// Keeps in `suites` only the tests `failed` names (by their id, model/test_id.h),
// and only the suites left with a test, whose fixtures then run as usual. A failed stop record
// of a suite's world ("world 'lab': stop of 'server'", isStopRecord) keeps the whole suite.
void keepFailedTests(std::vector<SuiteSpec>& suites, const std::vector<FailedTest>& failed);

// The name of the record of a world process that did not stop cleanly (the process fixture's
// "world 'NAME': stop of 'PROCESS'", docs/reference/world-file.md).
bool isStopRecord(const std::string& name);

}  // namespace runner
}  // namespace robottestingframework
