// What the kernel can do for a process's lifetime, and what the portable build does instead
// (process-posix.cpp uses these; they differ per platform, one file each: -linux, -portable).
#pragma once

#include <sys/types.h>

namespace robottestingframework {
namespace platform {

// In a child between fork and exec (async-signal-safe only): `signal` is sent to it when
// `parent` ends. False when the parent is already gone.
bool armParentDeathSignalInChild(int signal, pid_t parent);

// execvp with `envp` as the program's environment. Returns only on failure (errno set).
void execSearchingPath(const char* program, char* const argv[], char* const envp[]);

}  // namespace platform
}  // namespace robottestingframework
