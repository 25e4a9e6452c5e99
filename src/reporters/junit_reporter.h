// The JUnit XML output (the schema Jenkins, GitLab and GitHub read, schemas/junit.xsd): one
// testsuite per suite, one testcase per test.
#pragma once

#include "reporters/reporter.h"

namespace robottestingframework {
namespace reporters {

class JUnitReporter : public CumulativeReporter {
public:
    using CumulativeReporter::CumulativeReporter;
    void writeDocument(ReportText& out) override;
};

}  // namespace reporters
}  // namespace robottestingframework
