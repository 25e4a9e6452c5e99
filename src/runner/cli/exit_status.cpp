#include "runner/cli/exit_status.h"

#include <robottestingframework/TestStatus.h>

namespace robottestingframework {
namespace runner {

bool anythingFailed(const TestResultCollector& collector) {
    if (collector.failedCount() > 0) {
        return true;
    }
    for (const auto& suite : collector.suites()) {
        if (suite.fixtureFailed || !suite.succeeded()) {
            return true;
        }
    }
    return false;
}

int runStatus(const TestResultCollector& collector, bool failOnFlaky, int signal) {
    int status = anythingFailed(collector) ? somethingFailed : allPassed;
    if (failOnFlaky && collector.countOf(TestStatus::Flaky) > 0) {
        status = somethingFailed;
    }
    if (signal != 0) {
        status = interruptedBy(signal);
    }
    return status;
}

}  // namespace runner
}  // namespace robottestingframework
