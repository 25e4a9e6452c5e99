// Reads a TAP stream (Test Anything Protocol, versions 12, 13 and 14) as a program printed it:
// test points with their directives and YAML diagnostics, subtests (indented streams, and the
// older "# Subtest:" form), plans, comments and "Bail out!". It never throws: whatever does not
// follow the protocol is either kept as plain output or listed as a problem.
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {
namespace languages {

struct TapPoint {
    enum class Directive { None, Skip, Todo };

    bool ok = false;
    unsigned int number = 0;  // as printed, or its position when the line has no number
    std::string description;
    Directive directive = Directive::None;
    std::string reason;       // the directive's text
    std::string diagnostics;  // the YAML block after the point, without its --- and ... lines
    std::string subtest;      // the enclosing subtests' names ("outer > inner"); empty at top
    unsigned int line = 0;    // 1-based line of the point in the stream

    // A failing TODO point is expected to fail: it does not fail the stream.
    bool failed() const { return !ok && directive != Directive::Todo; }
};

// Something in the stream that makes it fail although no point failed: a plan that does not
// match, a plan in the middle, a missing plan, a test number out of sequence.
struct TapProblem {
    unsigned int line = 0;  // where it was noticed (0: at the end of the stream)
    std::string message;
};

struct TapStream {
    bool isTap = false;  // a version line, a plan or a test point at the top level
    int version = 12;
    std::vector<TapPoint> points;        // every level, in stream order
    std::vector<std::string> comments;   // "# ..." lines, without the "#", in order
    std::vector<std::string> otherText;  // lines that are not TAP, in order
    std::vector<TapProblem> problems;
    bool skipAll = false;  // "1..0 # SKIP reason" at the top level
    std::string skipReason;
    bool bailedOut = false;
    std::string bailOutReason;

    bool failed() const;  // a failing point, a problem or a bail out
};

TapStream parseTap(const std::string& text);

}  // namespace languages
}  // namespace robottestingframework
