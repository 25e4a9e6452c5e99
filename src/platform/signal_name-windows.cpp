// Windows: a process ends by an exception, not a signal. Its exit code is the exception code
// (NTSTATUS), which stands where a signal number stands on POSIX: "0xC0000005", named
// "access violation"; but for a worker's abort(), named "SIGABRT" (kAbortExitCode).
#include "platform/signal_name.h"

#include <cstdio>

namespace robottestingframework {
namespace platform {

namespace {

struct ExceptionName {
    unsigned long code;
    const char* description;
};

const ExceptionName kExceptions[] = {
    {0x80000003UL, "breakpoint"},
    {0xC0000005UL, "access violation"},
    {0xC0000006UL, "in-page error"},
    {0xC000001DUL, "illegal instruction"},
    {0xC0000025UL, "non-continuable exception"},
    {0xC000008CUL, "array bounds exceeded"},
    {0xC000008DUL, "floating-point denormal operand"},
    {0xC000008EUL, "floating-point division by zero"},
    {0xC0000090UL, "floating-point invalid operation"},
    {0xC0000091UL, "floating-point overflow"},
    {0xC0000094UL, "integer division by zero"},
    {0xC0000095UL, "integer overflow"},
    {0xC0000096UL, "privileged instruction"},
    {0xC00000FDUL, "stack overflow"},
    {0xC0000135UL, "a DLL it needs was not found"},
    {0xC000013AUL, "interrupted by Ctrl-C"},
    {0xC0000374UL, "heap corruption"},
    {0xC0000409UL, "stack buffer overrun (fail fast)"},
    {kAbortExitCode, "aborted"},
};

}  // namespace

std::string signalName(int signal) {
    if (static_cast<unsigned long>(signal) == kAbortExitCode) {
        return "SIGABRT";
    }
    char text[16];
    std::snprintf(text, sizeof(text), "0x%08lX", static_cast<unsigned long>(signal));
    return text;
}

int signalNumber(const std::string& name) {
    for (const ExceptionName& exception : kExceptions) {
        if (signalName(static_cast<int>(exception.code)) == name) {
            return static_cast<int>(exception.code);
        }
    }
    return 0;
}

int stopSignalNumber(const std::string& name) {
    static const struct {
        const char* name;
        int number;
    } kStopSignals[] = {{"SIGHUP", 1},   {"SIGINT", 2},   {"SIGQUIT", 3}, {"SIGKILL", 9},
                        {"SIGUSR1", 10}, {"SIGUSR2", 12}, {"SIGTERM", 15}};
    for (const auto& stop : kStopSignals) {
        if (name == stop.name) {
            return stop.number;
        }
    }
    return 0;
}

std::string signalDescription(int signal) {
    for (const ExceptionName& exception : kExceptions) {
        if (exception.code == static_cast<unsigned long>(signal)) {
            return exception.description;
        }
    }
    return "exception";
}

std::string programKilledBy(int signal) {
    return "crashed: " + crashName(signal);
}

}  // namespace platform
}  // namespace robottestingframework
