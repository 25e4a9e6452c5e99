// What an output file is when the run starts, to tell at its end whether another process wrote
// it meanwhile: two runs started in one folder (the default result.txt, or one -o name) each
// replaced the other's report without a word. The stamp is the file's identity (device and
// inode: a report written whole is a new file), size and time of its last change.
#pragma once

#include <string>

namespace robottestingframework {
namespace runner {

// The stamp of the file `path` names: "" when there is none, and for a FIFO or a device
// (written through, never replaced: /dev/stdout, a pipe).
std::string outputStamp(const std::string& path);

// The warning when the file at `path` no longer has the stamp `before` (taken when the run
// started): "the TYPE output PATH was written by another run while this one ran (at
// HH:MM:SS): this run's replaces it"; "" when it has (or it is written through).
std::string outputWrittenMeanwhile(const std::string& type, const std::string& path,
                                   const std::string& before);

}  // namespace runner
}  // namespace robottestingframework
