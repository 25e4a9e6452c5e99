// One event of a run as plain data: what a collector keeps, and what a worker process sends
// back to the runner. Nothing in it points into the test that produced it.
#pragma once

#include <cstdint>
#include <string>

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
        Rename,  // the test now goes by `message`'s text (a script's setName)
    };

    Kind kind = Kind::Report;
    std::string testName;      // the test (or suite) the event is about; empty for runner events
    std::uint64_t testId = 0;  // its Test::getId(); 0 for runner events
    TestMessage message;       // for Output, the printed text is the message
    bool passed = true;        // for Check: whether the check held
    double time = 0;           // seconds since the collector started, when it was received
    // The repetition of its test it happened in (1..N, see TestListener::startRepetition);
    // 0 when the test runs once, and for runner and suite events.
    unsigned int repetition = 0;
};

// The id of repetition `index` of the test `testId`: "<testId>#<index>". Given by the plan
// (test ids) and the repetition count, so the same in every output of one run.
std::string repetitionId(std::uint64_t testId, unsigned int index);
// What the start of a repetition says: "repetition <index>/<count>".
TestMessage repetitionMessage(unsigned int index, unsigned int count);

// "start-runner", "report", "check", ... (stable names, used by the JSON and wire formats).
const char* toString(ResultEvent::Kind kind);

// The state an event gives the test it is about (a failure: Failed, a crash: Crashed, ...);
// Passed for the events that leave the state as it is. A test's state is the highest one its
// events gave it. The one table of it: the collector, the event relay and the executors read it.
TestStatus stateOf(ResultEvent::Kind kind);

}  // namespace robottestingframework
