#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestStatus.h>

#include <cstddef>
#include <utility>

#include "core/events.h"

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

// The one table of event kinds, one row per kind, in Kind order. Its columns:
// - word: the kind's stable name (JSON, wire format), the word before a message;
// - state: the state it gives its test;
// - frame: what it frames: nothing, the run (start/end of the runner or a suite), a test (its
//   start, its end), or a repetition of its test (its start: inside its test, so the relays
//   forward it as any other event);
// - text: what its message holds: a message, what the test printed, the test's new name, or a
//   shared world's phase;
// - message: a test's message (report, check): the reports keep it whatever -v says;
// - check: a passed one is hidden unless passed checks are kept;
// - said: a line of its own under its test in the console, TAP and live page (failures,
//   skips, ...; a message is said as -v and the check column allow);
// - failFast: it trips --fail-fast (a retry takes it back);
// - lastWords: what a worker said last, quoted when it dies;
// - replayed: what a shared world's start said, said again to each suite that joins it (under
//   the suite's world test): its reports, output, attachments and measurements;
// - carries: its data (a measurement, an attachment); without it, it is said as any other;
// - tone: its colour in the console;
// - passedLabel / failedLabel: its word when it passed / failed (null: `word`), as the
//   console, text and TAP reports show it; failedName: as the HTML report and live page do.
enum class Carries : unsigned char { Nothing, Measurement, Attachment };
enum class Frame : unsigned char { No, Run, TestStart, TestEnd, Repetition };
enum class Text : unsigned char { Message, Printed, NewName, WorldPhase };
struct KindRow {
    ResultEvent::Kind kind;
    const char* word;
    TestStatus state;
    Frame frame;
    Text text;
    bool message;
    bool check;
    bool said;
    bool failFast;
    bool lastWords;
    bool replayed;
    Carries carries;
    KindTone tone;
    const char* passedLabel;
    const char* failedLabel;
    const char* failedName;
};
using Kind = ResultEvent::Kind;
using T = KindTone;
constexpr Carries none = Carries::Nothing;
constexpr Frame run = Frame::Run;
constexpr Frame no = Frame::No;
constexpr Text msg = Text::Message;
constexpr bool Y = true;
constexpr bool n = false;
// clang-format off
constexpr KindRow kindRows[] = {
//   kind              word            state                   frame              text              msg chk said ff  last rep carries               tone         passed      failed                       failedName
    {Kind::StartRunner, "start-runner", TestStatus::Passed,      run,               msg,              n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::EndRunner,   "end-runner",   TestStatus::Passed,      run,               msg,              n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::StartSuite,  "start-suite",  TestStatus::Passed,      run,               msg,              n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::EndSuite,    "end-suite",    TestStatus::Passed,      run,               msg,              n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::StartTest,   "start-test",   TestStatus::Passed,      Frame::TestStart,  msg,              n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::EndTest,     "end-test",     TestStatus::Passed,      Frame::TestEnd,    msg,              n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Report,      "report",       TestStatus::Passed,      no,                msg,              Y,  n,  n,   n,  Y,   Y, none,                 T::Plain,    nullptr,    nullptr,                     nullptr},
    {Kind::Check,       "check",        TestStatus::Passed,      no,                msg,              Y,  Y,  n,   n,  Y,   n, none,                 T::Outcome,  "check ok", "check FAILED",              "check failed"},
    {Kind::Failure,     "failure",      TestStatus::Failed,      no,                msg,              n,  n,  Y,   Y,  Y,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Error,       "error",        TestStatus::Error,       no,                msg,              n,  n,  Y,   Y,  Y,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Skipped,     "skipped",      TestStatus::Skipped,     no,                msg,              n,  n,  Y,   n,  n,   n, none,                 T::Warn,     nullptr,    nullptr,                     nullptr},
    {Kind::Crash,       "crash",        TestStatus::Crashed,     no,                msg,              n,  n,  Y,   Y,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Timeout,     "timeout",      TestStatus::TimedOut,    no,                msg,              n,  n,  Y,   Y,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Interrupted, "interrupted",  TestStatus::Interrupted, no,                msg,              n,  n,  Y,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Output,      "output",       TestStatus::Passed,      no,                Text::Printed,    n,  n,  n,   n,  n,   Y, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Rename,      "rename",       TestStatus::Passed,      no,                Text::NewName,    n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Retry,       "retry",        TestStatus::Passed,      no,                msg,              n,  n,  n,   Y,  n,   n, none,                 T::Warn,     nullptr,    nullptr,                     nullptr},
    {Kind::Repetition,  "repetition",   TestStatus::Passed,      Frame::Repetition, msg,              n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Measurement, "measurement",  TestStatus::Passed,      no,                msg,              n,  n,  n,   n,  n,   Y, Carries::Measurement, T::Bad,      nullptr,    "measurement OUTSIDE LIMITS", nullptr},
    {Kind::Attachment,  "attachment",   TestStatus::Passed,      no,                msg,              n,  n,  n,   n,  n,   Y, Carries::Attachment,  T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::World,       "world",        TestStatus::Passed,      no,                Text::WorldPhase, n,  n,  n,   n,  n,   n, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
    {Kind::Probe,       "probe",        TestStatus::Failed,      no,                msg,              n,  n,  Y,   n,  n,   Y, none,                 T::Bad,      nullptr,    nullptr,                     nullptr},
};
// clang-format on

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

namespace {

Frame frameOf(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr ? row->frame : Frame::No;
}

Text textOf(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr ? row->text : Text::Message;
}

}  // namespace

bool isFrame(ResultEvent::Kind kind) {
    const Frame frame = frameOf(kind);
    return frame == Frame::Run || frame == Frame::TestStart || frame == Frame::TestEnd;
}

bool startsTest(ResultEvent::Kind kind) {
    return frameOf(kind) == Frame::TestStart;
}

bool endsTest(ResultEvent::Kind kind) {
    return frameOf(kind) == Frame::TestEnd;
}

bool startsRepetition(ResultEvent::Kind kind) {
    return frameOf(kind) == Frame::Repetition;
}

bool isOutput(ResultEvent::Kind kind) {
    return textOf(kind) == Text::Printed;
}

bool renamesTest(ResultEvent::Kind kind) {
    return textOf(kind) == Text::NewName;
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

bool isMessage(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr && row->message;
}

bool isShown(const ResultEvent& event, bool passedChecks) {
    const KindRow* row = rowOf(event.kind);
    return row == nullptr || !row->check || !event.passed || passedChecks;
}

bool isHiddenCheck(const ResultEvent& event) {
    const KindRow* row = rowOf(event.kind);
    return row != nullptr && row->check && event.passed;
}

bool isFailedCheck(const ResultEvent& event) {
    const KindRow* row = rowOf(event.kind);
    return row != nullptr && row->check && !event.passed;
}

bool isCheck(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr && row->check;
}

bool carriesData(const ResultEvent& event) {
    const KindRow* row = rowOf(event.kind);
    if (row == nullptr) {
        return false;
    }
    switch (row->carries) {
        case Carries::Measurement:
            return event.measurement != nullptr;
        case Carries::Attachment:
            return event.attachment != nullptr;
        case Carries::Nothing:
            break;
    }
    return false;
}

bool isMeasurement(const ResultEvent& event) {
    const KindRow* row = rowOf(event.kind);
    return row != nullptr && row->carries == Carries::Measurement && event.measurement != nullptr;
}

bool isAttachment(const ResultEvent& event) {
    const KindRow* row = rowOf(event.kind);
    return row != nullptr && row->carries == Carries::Attachment && event.attachment != nullptr;
}

bool carriesAnything(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr && row->carries != Carries::Nothing;
}

bool isSaid(const ResultEvent& event) {
    const KindRow* row = rowOf(event.kind);
    if (row == nullptr) {
        return true;  // garbage from a broken worker: said, as an event like any other
    }
    return row->said || (row->carries != Carries::Nothing && !carriesData(event));
}

bool tripsFailFast(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr && row->failFast;
}

bool isLastWords(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr && row->lastWords;
}

bool isReplayed(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr && row->replayed;
}

KindTone toneOf(ResultEvent::Kind kind) {
    const KindRow* row = rowOf(kind);
    return row != nullptr ? row->tone : KindTone::Bad;
}

const char* labelOf(ResultEvent::Kind kind, bool passed) {
    const KindRow* row = rowOf(kind);
    if (row == nullptr) {
        return "unknown";
    }
    const char* label = passed ? row->passedLabel : row->failedLabel;
    return label != nullptr ? label : row->word;
}

bool isWorldPhase(ResultEvent::Kind kind) {
    return textOf(kind) == Text::WorldPhase;
}

const ResultEvent& shownEvent(const ResultEvent& event, ResultEvent& scratch) {
    if (!startsRepetition(event.kind)) {
        return event;
    }
    scratch.kind = Kind::Report;
    scratch.testName = event.testName;
    scratch.testId = event.testId;
    scratch.time = event.time;
    scratch.repetition = event.repetition;
    scratch.message = repetitionMessage(event.repetition, event.repetitions);
    return scratch;
}

const char* nameOf(ResultEvent::Kind kind, bool passed) {
    const KindRow* row = rowOf(kind);
    if (row == nullptr) {
        return "unknown";
    }
    return !passed && row->failedName != nullptr ? row->failedName : row->word;
}

namespace events {

// The makers by name, one per kind that something sends (the table above says what each is).

namespace {

ResultEvent made(Kind kind, TestMessage msg = TestMessage()) {
    ResultEvent event;
    event.kind = kind;
    event.message = std::move(msg);
    return event;
}

}  // namespace

ResultEvent startRunner() {
    return made(Kind::StartRunner);
}

ResultEvent endRunner() {
    return made(Kind::EndRunner);
}

ResultEvent startSuite() {
    return made(Kind::StartSuite);
}

ResultEvent endSuite() {
    return made(Kind::EndSuite);
}

ResultEvent startTest() {
    return made(Kind::StartTest);
}

ResultEvent endTest() {
    return made(Kind::EndTest);
}

ResultEvent report(TestMessage msg) {
    return made(Kind::Report, std::move(msg));
}

ResultEvent check(TestMessage msg, bool passed) {
    ResultEvent event = made(Kind::Check, std::move(msg));
    event.passed = passed;
    return event;
}

ResultEvent failure(TestMessage msg) {
    return made(Kind::Failure, std::move(msg));
}

ResultEvent error(TestMessage msg) {
    return made(Kind::Error, std::move(msg));
}

ResultEvent skipped(TestMessage reason) {
    return made(Kind::Skipped, std::move(reason));
}

ResultEvent crash(TestMessage msg) {
    return made(Kind::Crash, std::move(msg));
}

ResultEvent timeout(TestMessage msg) {
    return made(Kind::Timeout, std::move(msg));
}

ResultEvent interrupted(TestMessage msg) {
    return made(Kind::Interrupted, std::move(msg));
}

ResultEvent output(const std::string& text) {
    return made(Kind::Output, TestMessage(text));
}

ResultEvent rename(const std::string& name) {
    return made(Kind::Rename, TestMessage(name));
}

ResultEvent retry(TestMessage msg) {
    return made(Kind::Retry, std::move(msg));
}

ResultEvent repetition(unsigned int index, unsigned int count) {
    ResultEvent event = made(Kind::Repetition);
    event.repetition = index;
    event.repetitions = count;
    return event;
}

ResultEvent measurement(std::shared_ptr<const Measurement> measured, bool passed,
                        TestMessage described) {
    ResultEvent event = made(Kind::Measurement, std::move(described));
    event.passed = passed;
    event.measurement = std::move(measured);
    return event;
}

ResultEvent attachment(std::shared_ptr<const Attachment> attached, TestMessage described) {
    ResultEvent event = made(Kind::Attachment, std::move(described));
    event.attachment = std::move(attached);
    return event;
}

ResultEvent world(const std::string& name, const std::string& phase, const std::string& detail) {
    ResultEvent event = made(Kind::World, TestMessage(phase, detail));
    event.testName = name;
    return event;
}

}  // namespace events

}  // namespace robottestingframework
