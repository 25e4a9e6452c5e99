// --merge OUT_TYPE:OUT_FILE REPORT...: the JUnit or JSON (CTRF) reports of the shards of one run
// made into one report of the same format, as one machine running every suite would write it.
#pragma once

#include <string>
#include <vector>

#include "runner/reports/report_reader.h"

namespace robottestingframework {
namespace runner {

struct MergeRequest {
    std::string type;  // "junit" or "json"
    std::string file;
    std::vector<std::string> reports;
    unsigned int expectShards = 0;  // --expect-shards N; 0: not checked
};

// The merged document. Suites are in the order of their places in the whole run (each shard's
// report records them); a report written by --rerun-failed replaces the tests it ran again
// (its last attempt wins). Throws std::runtime_error naming the file and what is wrong: a
// report of another format, a suite in two shards, and with `expectShards` a shard missing,
// given twice, or of another count.
std::string mergeReports(const MergeRequest& request);

// The same over reports already read (request.reports is not read; the reports' own paths name
// them in messages).
std::string mergeReports(const MergeRequest& request, std::vector<Report> reports);

}  // namespace runner
}  // namespace robottestingframework
