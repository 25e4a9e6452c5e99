// One event of a run as plain data: what a collector keeps, and what a worker process sends
// back to the runner. Nothing in it points into the test that produced it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <robottestingframework/Attachment.h>
#include <robottestingframework/Measurement.h>

#include <robottestingframework/Test.h>  // as in RTF 2.x
#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestStatus.h>

namespace robottestingframework {

struct ResultEvent {
    enum class Kind : unsigned char {
        StartRunner,
        EndRunner,
        StartSuite,
        EndSuite,
        StartTest,
        EndTest,
        Report,
        Check,
        Failure,
        Error,
        Skipped,
        Crash,
        Timeout,
        Interrupted,
        Output,
        Rename,       // the test now goes by `message`'s text (a script's setName)
        Retry,        // the test just ended failing and runs again; `message` says which attempt
        Repetition,   // repetition `repetition` of `repetitions` of the test starts
        Measurement,  // the test measured `measurement`; `passed`: within its limits
        Attachment,   // the test attached `attachment` (already copied)
        // A world shared by suites (scope="run") changed: `testName` is the world's name,
        // `message` its phase ("start", "ready", "failed", "collapsed", "stop"; its detail: the
        // reason, or for "start" how many suites share it). About no test (testId 0): no named
        // handler; TestResultCollector::worlds() keeps it.
        World,
        // Reserved for the runner's own tests (tests/e2e/test_event_kinds.py): no product code
        // sends it. A kind with nothing but its rows in the tables (TestListener::addEvent
        // takes it): it fails its test, so every report shows whether it arrived.
        Probe,
    };
    // The last kind: a kind is added before it or takes its place here.
    static constexpr Kind lastKind = Kind::Probe;

    Kind kind = Kind::Report;
    std::string testName;      // the test (or suite) the event is about; empty for runner events
    std::uint64_t testId = 0;  // its Test::getId(); 0 for runner events
    TestMessage message;       // for Output, the printed text is the message
    bool passed = true;        // for Check: whether the check held
    double time = 0;           // seconds since the collector started, when it was received
    // The repetition of its test it happened in (1..N, see TestListener::startRepetition);
    // 0 when the test runs once, and for runner and suite events.
    unsigned int repetition = 0;
    unsigned int repetitions = 0;  // for Repetition: how many times the test runs
    // For Measurement and Attachment: what was measured or attached (shared, as events are
    // copied to every record and relay; null for every other kind).
    std::shared_ptr<const robottestingframework::Measurement> measurement = nullptr;
    std::shared_ptr<const robottestingframework::Attachment> attachment = nullptr;
};

// The id of repetition `index` of the test `testId`: "<testId>#<index>". Given by the plan
// (test ids) and the repetition count, so the same in every output of one run.
std::string repetitionId(std::uint64_t testId, unsigned int index);
// What the start of a repetition says: "repetition <index>/<count>".
TestMessage repetitionMessage(unsigned int index, unsigned int count);

// The tables of event kinds, one row per kind, in TestStatus.cpp: adding a kind is adding its
// rows there; the listeners, relays and the wire format need nothing else. What sends an event
// makes it by name (src/core/events.h, beside the table), and the relays ask the columns below:
// in src/, only the table and RTF 2.x's adapter (TestListener::onEvent) spell a kind.

// "start-runner", "report", "check", ... (stable names, used by the JSON and wire formats, and
// the word the console, TAP and live page put before a message).
const char* toString(ResultEvent::Kind kind);

// Whether the kind frames a run (start/end of the runner, a suite or a test) rather than says
// something about a test. A relay that frames a test itself (a worker's events about the
// runner's stand-in) forwards only the others.
bool isFrame(ResultEvent::Kind kind);
// Of the frames: the start and the end of a test.
bool startsTest(ResultEvent::Kind kind);
bool endsTest(ResultEvent::Kind kind);
// The start of a repetition of its test (`repetition` of `repetitions`): inside its test, not a
// frame (relays forward it).
bool startsRepetition(ResultEvent::Kind kind);
// Its message's text is what the test printed (kept as the test's output, not as a message).
bool isOutput(ResultEvent::Kind kind);
// Its message's text is the test's new name.
bool renamesTest(ResultEvent::Kind kind);

// The state an event gives the test it is about (a failure: Failed, a crash: Crashed, ...);
// Passed for the events that leave the state as it is. A test's state is the highest one its
// events gave it. The one table of it: the collector, the event relay and the executors read it.
TestStatus stateOf(ResultEvent::Kind kind);

// The other columns of that table: what a kind is to the listeners, so that none of them lists
// kinds of its own.
// A test's message (a report, a check): the reports keep it whatever -v says.
bool isMessage(ResultEvent::Kind kind);
// A check: a passed one is hidden unless passed checks are kept.
bool isCheck(ResultEvent::Kind kind);
// Whether `event` is shown, `passedChecks` saying whether passed checks are: all but a passed
// check when they are not.
bool isShown(const ResultEvent& event, bool passedChecks);
// A passed check (hidden unless passed checks are kept).
bool isHiddenCheck(const ResultEvent& event);
// A failed check: its failure, with the same message, follows it (Asserter::testCheck), so
// the console says that one line and not this one.
bool isFailedCheck(const ResultEvent& event);
// Whether the event is a line of its own under its test (failures, skips, crashes, a kind with
// no handler of its own, a measurement or attachment that lost its data): the console, TAP
// and the live page say it as it comes. Reports and checks are said as -v allows.
bool isSaid(const ResultEvent& event);
// Whether the event carries its data: a measurement, an attachment.
bool carriesData(const ResultEvent& event);
// Whether the kind carries data (measurements, attachments), with it or not.
bool carriesAnything(ResultEvent::Kind kind);
// A measurement / an attachment with its data.
bool isMeasurement(const ResultEvent& event);
bool isAttachment(const ResultEvent& event);
// Whether the kind trips --fail-fast (a failure, error, crash, timeout; a retry takes it back).
bool tripsFailFast(ResultEvent::Kind kind);
// Whether a worker saying it is quoted when the worker dies (its last words).
bool isLastWords(ResultEvent::Kind kind);
// Whether a shared world's start saying it is said again to each suite that joins the world.
bool isReplayed(ResultEvent::Kind kind);
// The kind's colour in the console: none, the check's outcome, a warning, a problem.
enum class KindTone : unsigned char { Plain, Outcome, Warn, Bad };
KindTone toneOf(ResultEvent::Kind kind);
// Its word as the console, text and TAP reports show it ("check FAILED", "failure", ...).
const char* labelOf(ResultEvent::Kind kind, bool passed);
// A shared world's phase (about no test): TestResultCollector::worlds() keeps them.
bool isWorldPhase(ResultEvent::Kind kind);
// What a listener shows of `event`: the event itself, except a repetition's start, shown as
// the report "repetition index/count" (as TestListener::startRepetition gives it to RTF 2.x's
// listeners), made in `scratch`.
const ResultEvent& shownEvent(const ResultEvent& event, ResultEvent& scratch);
// Its word as the HTML report and the live page show it ("check failed", "failure", ...).
const char* nameOf(ResultEvent::Kind kind, bool passed);

}  // namespace robottestingframework
