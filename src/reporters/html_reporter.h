// The HTML output: one self-contained file (inline CSS and JS, no network, opens from file://)
// with the summary, a pass/fail bar, the run's metadata, a timeline (one lane per suite running
// at once: fixture setup with its processes' readiness, tests, teardown), suites as a tree with
// failures open and their first message in the row, a filter by state (flaky tests under
// Failing), a search box, an order by duration, per-test sections (identity, messages, attempts,
// output), the slowest tests shown, light and dark themes. The page is src/reporters/html_page/.
// Test text is data: embedded as JSON with '<' escaped and shown with textContent only. The DOM
// of a suite is built when it is opened, and in pages, so 10 000 tests stay usable.
#pragma once

#include <cstddef>

#include "reporters/reporter.h"

namespace robottestingframework {
namespace reporters {

class HtmlReporter : public CumulativeReporter {
public:
    using CumulativeReporter::CumulativeReporter;
    void writeDocument(ReportText& out) override;
    // The JSON the page reads for one test and one suite (with its tests).
    std::string testData(const TestRecord& test, const SuiteRecord& suite) const;
    std::string suiteData(const SuiteRecord& suite) const;
    void writeSuiteData(ReportText& out, const SuiteRecord& suite) const;

    // What a test printed is cut to this many bytes in the page, with a note saying so.
    static constexpr std::size_t outputCap = 64 * 1024;
};

}  // namespace reporters
}  // namespace robottestingframework
