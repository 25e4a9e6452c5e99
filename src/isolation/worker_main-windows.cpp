// robottestingframework-worker.exe: the runner's helper process on Windows, one per test.
// Started by the runner as
//   robottestingframework-worker.exe --worker IN OUT
// with IN and OUT inherited pipe handles: its request comes on IN (request_pipe.h), its events
// go out on OUT in the wire format; not meant to be run by hand.
#include <fcntl.h>
#include <io.h>
#include <windows.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "isolation/request_pipe.h"
#include "isolation/worker.h"
#include "platform/job_process.h"
#include "platform/signal_name.h"

namespace {

// A crash ends the worker at once with its exception code (the runner names it), instead of
// the system's error dialog or Wine's debugger.
LONG WINAPI endWithExceptionCode(EXCEPTION_POINTERS* exception) {
    ::TerminateProcess(::GetCurrentProcess(), exception->ExceptionRecord->ExceptionCode);
    return EXCEPTION_EXECUTE_HANDLER;
}

// abort() (a test's own, or std::terminate's) raises SIGABRT and then ends the program with
// status 3, which cannot be told from exit(3): the worker ends with its own code instead, which
// the runner names SIGABRT as POSIX does. abort() calls the handler on the aborting thread.
void endAborted(int) {
    std::fflush(stdout);
    std::fflush(stderr);
    ::TerminateProcess(::GetCurrentProcess(), robottestingframework::platform::kAbortExitCode);
}

}  // namespace

int main(int argc, char** argv) {
    using namespace robottestingframework;
    if (argc == 4 && std::strcmp(argv[1], "--worker") == 0) {
        const int calls = platform::descriptorOfHandle(argv[2]);
        const int events = platform::descriptorOfHandle(argv[3]);
        isolation::WorkRequest request;
        if (calls >= 0 && events >= 0 && isolation::readRequest(calls, request)) {
            ::SetErrorMode(SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
            ::SetUnhandledExceptionFilter(endWithExceptionCode);
            std::signal(SIGABRT, endAborted);
            // Line by line, as on POSIX: what a test printed before it crashed is not lost.
            std::setvbuf(stdout, nullptr, _IOLBF, 4096);
            for (const auto& variable : request.variables) {
                const std::size_t equals = variable.find('=');
                if (equals != std::string::npos) {
                    ::_putenv_s(variable.substr(0, equals).c_str(), variable.c_str() + equals + 1);
                }
            }
            if (request.role == isolation::WorkRequest::Role::Test) {
                return isolation::runTestWorker(request, events);
            }
        }
    }
    std::fprintf(stderr,
                 "%s: the test runner's worker; it is started by robottestingframework-testrunner "
                 "(usage: %s --worker IN OUT)\n",
                 argv[0], argv[0]);
    return 2;
}
