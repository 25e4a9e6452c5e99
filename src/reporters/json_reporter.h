// The JSON output in CTRF, the Common Test Report Format (https://ctrf.io): a summary and one
// entry per test; what CTRF has no word for (error vs failure, crash, timeout, fixtures) sits
// under "extra" -> "robotology.rtf" (the namespaced key; "rtf" before). The mapping is in
// docs/reference/ctrf.md.
#pragma once

#include "reporters/reporter.h"

namespace robottestingframework {
namespace reporters {

class JsonReporter : public CumulativeReporter {
public:
    using CumulativeReporter::CumulativeReporter;
    void writeDocument(ReportText& out) override;
};

}  // namespace reporters
}  // namespace robottestingframework
