// Names for signals and process endings, as the reports show them.
#pragma once

#include <string>

namespace robottestingframework {
namespace platform {

// "SIGSEGV", "SIGABRT", ... ; "SIGRTMIN+3"; "signal 99" for unknown numbers.
std::string signalName(int signal);
// The number of a signal named as signalName() names it ("SIGTERM"); 0 when none is.
int signalNumber(const std::string& name);
// The number of a signal that asks a process to stop, named as on POSIX ("SIGTERM", "SIGINT"):
// signalNumber() there. Windows has no such signals (a process is stopped by ending its job):
// there the POSIX numbers of SIGHUP, SIGINT, SIGQUIT, SIGKILL, SIGUSR1, SIGUSR2 and SIGTERM, so
// that a file naming one reads the same on both. 0 when none is.
int stopSignalNumber(const std::string& name);
// The platform's description: "Segmentation fault".
std::string signalDescription(int signal);
// A crash as the reports name it after "crashed: ": "SIGSEGV (Segmentation fault)"; on Windows
// "0xC0000005 (access violation)", "SIGABRT (aborted)".
std::string crashName(int signal);
// What an exec test's report says of a program a signal or an exception ended: "killed by
// SIGSEGV" on POSIX (the wording exec tests always had); on Windows as a worker's crash,
// "crashed: 0xC0000005 (access violation)".
std::string programKilledBy(int signal);

#ifdef _WIN32
// The exit code a worker ends with when its test calls abort(): MinGW's (msvcrt's) abort()
// ends a program with status 3, which exit(3) gives too, so the worker's SIGABRT handler ends
// it with this one instead. An application's own error status (NTSTATUS with the customer bit:
// 0xE...), 22 being SIGABRT in <signal.h>; named "SIGABRT" here, as on POSIX.
constexpr unsigned long kAbortExitCode = 0xE0000016UL;
#endif

}  // namespace platform
}  // namespace robottestingframework
