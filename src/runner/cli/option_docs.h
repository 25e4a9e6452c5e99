// The man page and the command-line reference (docs/reference/command-line.md), made from the
// option table as --help is: `--help-man` and `--help-markdown` print them (the build writes
// the man page; tests/e2e/test_command_line_docs.py checks the reference is up to date).
#pragma once

#include <string>
#include <vector>

#include "runner/cli/option_table.h"

namespace robottestingframework {
namespace runner {

// robottestingframework-testrunner.1, in roff.
std::string manPage(const std::vector<OptionRow>& rows, const std::string& version);

// The reference page, in Markdown; the same for every build of a version's sources.
std::string markdownReference(const std::vector<OptionRow>& rows);

}  // namespace runner
}  // namespace robottestingframework
