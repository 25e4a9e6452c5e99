#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestStatus.h>

#include <cstddef>

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

namespace {

// The one table of event kinds: each kind's word, the state it gives its test, and whether it
// frames the run rather than says something about a test.
struct KindRow {
    ResultEvent::Kind kind;
    const char* word;
    TestStatus state;
    bool frame;
};
using Kind = ResultEvent::Kind;
constexpr KindRow kindRows[] = {
    {Kind::StartRunner, "start-runner", TestStatus::Passed, true},
    {Kind::EndRunner, "end-runner", TestStatus::Passed, true},
    {Kind::StartSuite, "start-suite", TestStatus::Passed, true},
    {Kind::EndSuite, "end-suite", TestStatus::Passed, true},
    {Kind::StartTest, "start-test", TestStatus::Passed, true},
    {Kind::EndTest, "end-test", TestStatus::Passed, true},
    {Kind::Report, "report", TestStatus::Passed, false},
    {Kind::Check, "check", TestStatus::Passed, false},
    {Kind::Failure, "failure", TestStatus::Failed, false},
    {Kind::Error, "error", TestStatus::Error, false},
    {Kind::Skipped, "skipped", TestStatus::Skipped, false},
    {Kind::Crash, "crash", TestStatus::Crashed, false},
    {Kind::Timeout, "timeout", TestStatus::TimedOut, false},
    {Kind::Interrupted, "interrupted", TestStatus::Interrupted, false},
    {Kind::Output, "output", TestStatus::Passed, false},
    {Kind::Rename, "rename", TestStatus::Passed, false},
    {Kind::Retry, "retry", TestStatus::Passed, false},
    {Kind::Repetition, "repetition", TestStatus::Passed, false},
    {Kind::Measurement, "measurement", TestStatus::Passed, false},
    {Kind::Attachment, "attachment", TestStatus::Passed, false},
    {Kind::World, "world", TestStatus::Passed, false},
    {Kind::Probe, "probe", TestStatus::Failed, false},
};

constexpr bool inKindOrder() {
    std::size_t at = 0;
    for (const KindRow& row : kindRows) {
        if (static_cast<std::size_t>(row.kind) != at++) {
            return false;
        }
    }
    return true;
}
static_assert(inKindOrder(), "kindRows: one row per ResultEvent::Kind, in its order");
static_assert(static_cast<std::size_t>(ResultEvent::lastKind) + 1 ==
                  sizeof(kindRows) / sizeof(kindRows[0]),
              "kindRows: a row for every ResultEvent::Kind");

const KindRow* rowOf(Kind kind) {
    // The rows are in Kind order; a value past the table (garbage) has none.
    const auto at = static_cast<std::size_t>(kind);
    return at < sizeof(kindRows) / sizeof(kindRows[0]) ? &kindRows[at] : nullptr;
}

}  // namespace

const char* toString(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr ? row->word : "unknown";
}

bool isFrame(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr && row->frame;
}

std::string repetitionId(std::uint64_t testId, unsigned int index) {
    return std::to_string(testId) + "#" + std::to_string(index);
}

TestMessage repetitionMessage(unsigned int index, unsigned int count) {
    return TestMessage("repetition " + std::to_string(index) + "/" + std::to_string(count));
}

TestStatus stateOf(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr ? row->state : TestStatus::Passed;
}

}  // namespace robottestingframework
