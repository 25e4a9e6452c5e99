// The run's attachments folder (docs/how-to/measurements-and-attachments.md): rtf-attachments/
// beside the first file output (the current folder without one), made by the first attachment and
// emptied when a run starts, and named to the tests through RTF_ATTACHMENTS_DIR, which the workers
// inherit. A folder the user named in RTF_ATTACHMENTS_DIR is used as it is.
#pragma once

#include <string>

#include "runner/cli/options.h"

namespace robottestingframework {
namespace runner {

// False with `error` naming the folder when it is a symbolic link or cannot be emptied.
bool prepareAttachmentsFolder(const Options& options, std::string& error);

}  // namespace runner
}  // namespace robottestingframework
