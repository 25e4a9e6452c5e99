// The text output: suites, each test's state and messages, and the run's summary.
#pragma once

#include "reporters/reporter.h"

namespace robottestingframework {
namespace reporters {

class TextReporter : public CumulativeReporter {
public:
    using CumulativeReporter::CumulativeReporter;
    void writeDocument(ReportText& out) override;
};

}  // namespace reporters
}  // namespace robottestingframework
