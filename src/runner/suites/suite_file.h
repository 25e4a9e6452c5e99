// Reading a suite file (SPEC 2, "Suite files") into a SuiteSpec. Strict: anything the runner
// would not understand is an error naming the file and line, never silently ignored.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "runner/model/suite_model.h"
#include "variables/variables.h"

namespace robottestingframework {
namespace runner {

// what() is "FILE:LINE: what was wrong and what was expected".
class SuiteFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The largest suite file read, in bytes: a suite of 100 000 tests is a few MiB.
constexpr std::size_t maxSuiteFileBytes = 16 * 1024 * 1024;

// Reads and checks `path`, a regular file of at most maxSuiteFileBytes. Plug-in names are resolved
// next to the suite file, then on the library search path (TestSpec::path stays empty when not
// found: the test then fails to load). Non-fatal remarks (the old `suit` root) are appended to
// `warnings`. ${...} is expanded with `commandLine` (--var, --var-file) over the suite's own
// <variable>s; a <test file="..."> is read in and expanded with the suite's variables over its
// own defaults. Process fixtures get every variable in their param (--var NAME=VALUE).
SuiteSpec readSuiteFile(const std::string& path, std::vector<std::string>& warnings,
                        const std::vector<variables::Variable>& commandLine = {});

// The same from text already read; `path` names it in messages and gives the folder plug-ins
// are looked for in.
SuiteSpec parseSuite(const std::string& text, const std::string& path,
                     std::vector<std::string>& warnings,
                     const std::vector<variables::Variable>& commandLine = {});

// A test file's text (what <test file="..."/> reads) on its own, as a suite naming it without
// attributes would read it with `suiteVariables` defined. `path` names it in messages.
TestSpec parseTestFile(const std::string& text, const std::string& path,
                       std::vector<std::string>& warnings,
                       const std::vector<variables::Variable>& suiteVariables = {});

}  // namespace runner
}  // namespace robottestingframework
