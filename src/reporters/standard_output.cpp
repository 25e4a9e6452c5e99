#include "reporters/standard_output.h"

#include "platform/output_file.h"

namespace robottestingframework {
namespace reporters {

namespace {

constexpr int standardOutputDescriptor = 1;
constexpr int standardErrorDescriptor = 2;

// The standard output the reports write to when keepStandardOutputForReports() moved it.
int reportsOutput = -1;

}  // namespace

bool namesStandardOutput(const std::string& filename) {
    return filename == "-" || filename == "/dev/stdout";
}

int openStandardOutput() {
    platform::flushStandardStreams();
    return platform::copyDescriptor(reportsOutput >= 0 ? reportsOutput : standardOutputDescriptor);
}

bool keepStandardOutputForReports() {
    if (reportsOutput >= 0) {
        return true;
    }
    platform::flushStandardStreams();
    const int kept = platform::copyDescriptor(standardOutputDescriptor);
    if (kept < 0) {
        return false;
    }
    if (!platform::pointDescriptor(standardErrorDescriptor, standardOutputDescriptor)) {
        platform::closeDescriptor(kept);
        return false;
    }
    reportsOutput = kept;
    return true;
}

}  // namespace reporters
}  // namespace robottestingframework
