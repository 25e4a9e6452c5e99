#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestStatus.h>

namespace robottestingframework {

const char* toString(TestStatus status) {
    switch (status) {
        case TestStatus::Passed:
            return "passed";
        case TestStatus::Skipped:
            return "skipped";
        case TestStatus::Failed:
            return "failed";
        case TestStatus::Error:
            return "error";
        case TestStatus::Crashed:
            return "crashed";
        case TestStatus::TimedOut:
            return "timed out";
        case TestStatus::Interrupted:
            return "interrupted";
        case TestStatus::Flaky:
            return "flaky";
    }
    return "unknown";
}

const char* toString(ResultEvent::Kind kind) {
    using Kind = ResultEvent::Kind;
    switch (kind) {
        case Kind::StartRunner:
            return "start-runner";
        case Kind::EndRunner:
            return "end-runner";
        case Kind::StartSuite:
            return "start-suite";
        case Kind::EndSuite:
            return "end-suite";
        case Kind::StartTest:
            return "start-test";
        case Kind::EndTest:
            return "end-test";
        case Kind::Report:
            return "report";
        case Kind::Check:
            return "check";
        case Kind::Failure:
            return "failure";
        case Kind::Error:
            return "error";
        case Kind::Skipped:
            return "skipped";
        case Kind::Crash:
            return "crash";
        case Kind::Timeout:
            return "timeout";
        case Kind::Interrupted:
            return "interrupted";
        case Kind::Output:
            return "output";
    }
    return "unknown";
}

TestStatus stateOf(ResultEvent::Kind kind) {
    using Kind = ResultEvent::Kind;
    switch (kind) {
        case Kind::Failure:
            return TestStatus::Failed;
        case Kind::Error:
            return TestStatus::Error;
        case Kind::Crash:
            return TestStatus::Crashed;
        case Kind::Timeout:
            return TestStatus::TimedOut;
        case Kind::Interrupted:
            return TestStatus::Interrupted;
        case Kind::Skipped:
            return TestStatus::Skipped;
        default:
            return TestStatus::Passed;
    }
}

}  // namespace robottestingframework
