// Starting programs and looking after our own process: the parent-death signal, the
// subreaper role, how a child ended.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace robottestingframework {
namespace platform {

struct SpawnOptions {
    std::vector<std::string> argv;         // argv[0] is the program (a path, or searched)
    std::string program;                   // the file to run instead of argv[0]
    std::string workingDirectory;          // the child's; ours when empty
    std::vector<std::pair<int, int>> fds;  // {descriptor in the child, ours}; others closed
    bool newProcessGroup = true;           // the child leads a group of its own
    int parentDeathSignal = 0;             // sent to the child when we die; 0: none
    bool nullStdin = true;                 // stdin is /dev/null unless `fds` maps 0
    // Set in (or added to) the child's environment, which is ours otherwise.
    std::vector<std::pair<std::string, std::string>> environment;
};

// Starts a program, with every signal at its default disposition. Returns its pid, or -1 with
// `error` set (including exec failures, which are reported back from the child; a script whose
// #! interpreter is missing is reported as such).
// `errorNumber`, when given, gets the errno of a failure.
pid_t spawnProcess(const SpawnOptions& options, std::string& error, int* errorNumber = nullptr);

// How a child ended, from a wait status.
struct ExitStatus {
    bool signaled = false;
    int code = 0;    // exit code when not signaled
    int signal = 0;  // the signal that ended it when signaled
    bool coreDumped = false;
    static ExitStatus fromWaitStatus(int status);
    // "exited with status 3", "killed by SIGSEGV (Segmentation fault)".
    std::string toString() const;
    bool success() const { return !signaled && code == 0; }
};

// A descriptor that becomes readable when our child `pid` ends (close-on-exec; a pidfd on
// Linux); -1 where the system has none: then the caller polls.
int openExitNotifier(pid_t pid);

// Waits up to `timeoutSeconds` (<0: forever) for our child `pid`; false while it still runs.
bool waitChild(pid_t pid, double timeoutSeconds, int& status);

// Orphaned descendants are re-parented to us instead of init (Linux; false in the portable
// build, where our children's process groups are how we reach their descendants).
bool becomeSubreaper();
// `signal` is delivered to us when our parent ends: on Linux when the thread that forked us
// ends (any process); in the portable build only in a process forked (not exec'd) from one that
// called prepareChildrenParentDeath() first, false otherwise. Call it between fork and other
// work: the portable build forks a guard (process_lifetime-portable.cpp).
bool setParentDeathSignal(int signal);
// Lets children forked from now on use setParentDeathSignal (the portable build's lifeline
// pipe; nothing on Linux). spawnProcess does it itself.
void prepareChildrenParentDeath();

// How many threads this process has (/proc/self/task); 0 when unknown. A fork keeps only the
// calling one.
std::size_t threadCount();
// threadCount(), waiting up to `waitMs` for it to fall to `atMost`: a thread that was just
// joined is still counted for a moment (the kernel wakes the joiner before it unlinks the
// thread). Returns the last count read.
std::size_t threadCountSettled(std::size_t atMost, int waitMs);
// The descriptors this process has open (/proc/self/fd), in increasing order.
std::vector<int> openDescriptors();

// The path of the running program (/proc/self/exe), empty when unknown.
std::string executablePath();

// The argv that runs `text` in the system's shell: {/bin/sh, -c, text} on POSIX,
// {cmd.exe, /d, /s, /c, text} on Windows (JobProcess passes what follows "/s /c" as cmd reads
// it: as it is, in one pair of quotes).
std::vector<std::string> shellCommand(const std::string& text);

}  // namespace platform
}  // namespace robottestingframework
