// A report written to the standard output: `--output json:-` or `--output junit:/dev/stdout`,
// into a terminal, a file or a pipe (`| jq`). "-" and "/dev/stdout" name it for every output
// kind; the runner then sends everything else it would print there (the console, the notes)
// to the standard error, so the standard output carries the report alone.
#pragma once

#include <string>

namespace robottestingframework {
namespace reporters {

// True for "-" and "/dev/stdout": the names of the standard output.
bool namesStandardOutput(const std::string& filename);

// A new descriptor on the standard output the reports write to (the caller closes it), after
// the C streams are flushed so that the report comes after what was printed before; -1 with
// errno set on failure.
int openStandardOutput();

// Keeps the current standard output for the reports alone and points descriptor 1 at the
// standard error, where the console and every other line of the runner then go. Once per
// process (later calls do nothing); false with errno set when the descriptors cannot be moved.
bool keepStandardOutputForReports();

}  // namespace reporters
}  // namespace robottestingframework
