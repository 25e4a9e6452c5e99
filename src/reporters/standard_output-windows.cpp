#include "reporters/standard_output.h"

#include <io.h>

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
    return ::_dup(reportsOutput >= 0 ? reportsOutput : 1);
}

bool keepStandardOutputForReports() {
    if (reportsOutput >= 0) {
        return true;
    }
    flushStreams();
    const int kept = ::_dup(1);
    if (kept < 0) {
        return false;
    }
    if (::_dup2(2, 1) != 0) {
        ::_close(kept);
        return false;
    }
    reportsOutput = kept;
    return true;
}

}  // namespace reporters
}  // namespace robottestingframework
