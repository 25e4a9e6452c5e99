// A report of an earlier run loaded into the history (--history-import): this runner's JUnit
// or CTRF report read as report_reader.h reads it, or another tool's, read leniently: JUnit
// (<testsuites> or one <testsuite>, each <testcase> with its time, <failure>, <error>,
// <skipped>) and CTRF (results.tests with name, status, duration, suite, retries, flaky).
#pragma once

#include <string>
#include <vector>

#include "runner/reports/report_reader.h"

namespace robottestingframework {
namespace runner {

struct ImportedReport {
    std::vector<ReportedTest> tests;
    std::vector<ReportedSuite> suites;
    double started = -1;  // seconds since the Unix epoch when the report says; else -1
    bool ours = false;    // written by this runner
    // The report's bytes digested (FNV-1a, 16 hex digits): the same report imported again, by
    // any path, is known by it.
    std::string digest;
};

// Throws std::runtime_error "--history-import FILE[:LINE]: ..." when the file cannot be read or
// is neither JUnit nor CTRF.
ImportedReport readImportedReport(const std::string& path);

}  // namespace runner
}  // namespace robottestingframework
