// Portable POSIX: fork's handling of page tables is the system's own; nothing to prepare.
#include "platform/fork_template.h"

namespace robottestingframework {
namespace platform {

void shareCodePagesWithForks() {}

}  // namespace platform
}  // namespace robottestingframework
