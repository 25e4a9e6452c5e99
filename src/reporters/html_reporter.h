// The HTML output: one self-contained file (inline CSS and JS, no network, opens from file://)
// with the summary, a pass/fail bar, suites as a tree with failures open, a filter by state, a
// search box, per-test messages, output and durations, the slowest tests, light and dark themes.
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
    std::string document() override;

    // What a test printed is cut to this many bytes in the page, with a note saying so.
    static constexpr std::size_t outputCap = 64 * 1024;
};

}  // namespace reporters
}  // namespace robottestingframework
