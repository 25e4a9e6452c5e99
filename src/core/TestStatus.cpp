#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestStatus.h>

namespace robottestingframework {

namespace {

// The one table of state words, in TestStatus order: the plain word, and the word as the
// text report's per-test lines show it.
struct StateWords {
    TestStatus status;
    const char* word;
    const char* label;
};
constexpr StateWords stateWords[] = {
    {TestStatus::Passed, "passed", "passed"},
    {TestStatus::Skipped, "skipped", "skipped"},
    {TestStatus::Failed, "failed", "FAILED"},
    {TestStatus::Error, "error", "ERROR"},
    {TestStatus::Crashed, "crashed", "CRASHED"},
    {TestStatus::TimedOut, "timed out", "TIMED OUT"},
    {TestStatus::Interrupted, "interrupted", "INTERRUPTED"},
    {TestStatus::Flaky, "flaky", "FLAKY"},
};

const StateWords* wordsOf(TestStatus status) {
    for (const StateWords& words : stateWords) {
        if (words.status == status) {
            return &words;
        }
    }
    return nullptr;
}

}  // namespace

const char* toString(TestStatus status) {
    const StateWords* words = wordsOf(status);
    return words != nullptr ? words->word : "unknown";
}

const char* toLabel(TestStatus status) {
    const StateWords* words = wordsOf(status);
    return words != nullptr ? words->label : "?";
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
        case Kind::Rename:
            return "rename";
    }
    return "unknown";
}

std::string repetitionId(std::uint64_t testId, unsigned int index) {
    return std::to_string(testId) + "#" + std::to_string(index);
}

TestMessage repetitionMessage(unsigned int index, unsigned int count) {
    return TestMessage("repetition " + std::to_string(index) + "/" + std::to_string(count));
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
