#include "reporters/standard_output.h"

#include "platform/output_file.h"
#include "reporters/standard_output_descriptor.h"

namespace robottestingframework {
namespace reporters {

namespace {

// The standard output the reports write to when keepStandardOutputForReports() moved it.
int reportsOutput = -1;

}  // namespace

bool namesStandardOutput(const std::string& filename) {
    return filename == "-" || filename == "/dev/stdout";
}

int openStandardOutput() {
    platform::flushStandardStreams();
    return duplicateDescriptor(reportsOutput >= 0 ? reportsOutput : standardOutputDescriptor);
}

bool keepStandardOutputForReports() {
    if (reportsOutput >= 0) {
        return true;
    }
    platform::flushStandardStreams();
    const int kept = duplicateDescriptor(standardOutputDescriptor);
    if (kept < 0) {
        return false;
    }
    if (!pointDescriptor(standardErrorDescriptor, standardOutputDescriptor)) {
        closeDescriptor(kept);
        return false;
    }
    reportsOutput = kept;
    return true;
}

}  // namespace reporters
}  // namespace robottestingframework
