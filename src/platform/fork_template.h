// A process that forks many short-lived children (the fork server) can hand them the page
// tables of its program's and libraries' code and read-only data, so that each child does not
// fault in again, 16 pages per fault, the code it runs after the fork. Linux only
// (fork_template-linux.cpp); elsewhere, and where the kernel refuses, nothing changes
// (-portable.cpp).
#pragma once

namespace robottestingframework {
namespace platform {

// Call once, single-threaded, before forking the children. From then on each fork copies this
// process's page-table entries of those mappings (a few nanoseconds each, in the parent's fork
// instead of page faults in the child's run). Contents and protections stay as they were.
void shareCodePagesWithForks();

}  // namespace platform
}  // namespace robottestingframework
