// Wording shared by the text reporters: status words, message lines, the run's summary.
#pragma once

#include <string>
#include <vector>

#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestStatus.h>

namespace robottestingframework {
namespace reporters {

// The console's colours (ANSI), and a test's by its state: green passed, yellow skipped, red
// any failure.
namespace colour {
constexpr const char* red = "\033[31m";
constexpr const char* green = "\033[32m";
constexpr const char* yellow = "\033[33m";
constexpr const char* bold = "\033[1m";
constexpr const char* plain = "\033[0m";
}  // namespace colour
const char* colourOf(TestStatus status);

// "passed", "skipped", then the failing states in capitals: "FAILED", "TIMED OUT", ...
const char* statusWord(TestStatus status);
// What a message line starts with: "failure", "error", "check FAILED", ...
std::string eventLabel(ResultEvent::Kind kind, bool passed);
// "message: detail [file:line]", then the message's diagnostics (a TAP point's YAML keys) as
// a block of lines under it (diagnosticsBlock).
std::string messageText(const TestMessage& msg);
// messageText's first line: "message: detail [file:line]", without the diagnostics.
std::string messageLine(const TestMessage& msg);
// The message's diagnostics as lines under it, each "\n  key: value" (a value that spans lines:
// "\n  key:" and its lines indented two more); "" without any.
std::string diagnosticsBlock(const TestMessage& msg);
// messageText as a terminal or the text report shows it: control characters escaped, and each
// line after its first starting with `continuation` (deeper than the line it is under), so
// that no message fakes a line of the console (text_safety.h, visibleText).
std::string shownMessage(const TestMessage& msg, const char* continuation);
// Every problem of a test (failure, error, crash, ...), one "kind: message" per line: the
// trace of the HTML and JSON reports.
std::string traceText(const std::vector<ResultEvent>& events);
// A test's output as the consoles show it under the test: one "      | line" per line.
std::vector<std::string> outputLines(const std::string& text);
// How the consoles and the text report name a test: its id in its suite, then the name it gives
// itself in parentheses when that differs ("tests/arith.lua (ArmTest)"); either alone when the
// other is empty, and the id alone when the name is an absolute path (a loader's default).
// Control characters in them shown escaped (text_safety.h, visibleText).
std::string shownAs(const std::string& key, const std::string& name);
// The same appended to `text`: the console's line of each test, with no string of its own.
void appendShownAs(std::string& text, const std::string& key, const std::string& name);
// How the consoles name a test, the same at every -j: the id --filter takes, "SUITE/KEY"
// (docs/reference/test-ids.md), then the name it gives itself as shownAs does
// ("robot/tests/arith.lua (ArmTest)"). Without a key, as shownAs.
void appendShownId(std::string& text, const std::string& suite, const std::string& key,
                   const std::string& name);
std::string shownId(const std::string& suite, const std::string& key, const std::string& name);
// "0.002 s".
std::string seconds(double value);

// The summary lines (tests per state, suites, wall time), without the closing line.
std::vector<std::string> summaryLines(const TestResultCollector& collector);
// "N passed, N failed" and ", N skipped" when there are any; a suite whose fixture failed counts
// once as failed.
std::string closingLine(const TestResultCollector& collector);

}  // namespace reporters
}  // namespace robottestingframework
