#include "reporters/standard_output.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace robottestingframework {
namespace reporters {

namespace {

// The standard output the reports write to when keepStandardOutputForReports() moved it.
int reportsOutput = -1;

void flushStreams() {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(stdout);
    std::fflush(stderr);
}

}  // namespace

int openStandardOutput() {
    flushStreams();
    return ::fcntl(reportsOutput >= 0 ? reportsOutput : STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
}

bool keepStandardOutputForReports() {
    if (reportsOutput >= 0) {
        return true;
    }
    flushStreams();
    const int kept = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
    if (kept < 0) {
        return false;
    }
    if (::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
        ::close(kept);
        return false;
    }
    reportsOutput = kept;
    return true;
}

}  // namespace reporters
}  // namespace robottestingframework
