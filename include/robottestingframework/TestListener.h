// Receives the events of a run. Every event arrives at onEvent; by default onEvent calls the
// named handler of its kind (the RTF 2.x ones and those added since), and every named handler
// does nothing unless overridden. A listener overrides the named handlers it cares about, as
// with RTF 2.x, or onEvent to take every event as data (a relay, a queue).
#pragma once

#include <string>

#include <robottestingframework/RunEvent.h>
#include <robottestingframework/Test.h>  // as in RTF 2.x
#include <robottestingframework/TestMessage.h>

namespace robottestingframework {

class TestSuite;

class TestListener {
public:
    virtual ~TestListener() = default;

    // The RTF 2.x events.
    virtual void addReport(const Test* /*test*/, TestMessage /*msg*/) {}
    virtual void addError(const Test* /*test*/, TestMessage /*msg*/) {}
    virtual void addFailure(const Test* /*test*/, TestMessage /*msg*/) {}
    virtual void startTest(const Test* /*test*/) {}
    virtual void endTest(const Test* /*test*/) {}
    // A suite starts or ends. Override either form: these call the `const Test*` ones, which
    // RTF 2.x's listeners override (RTF 2.x passed the suite as a Test).
    virtual void startTestSuite(const TestSuite* suite);
    virtual void endTestSuite(const TestSuite* suite);
    virtual void startTestSuite(const Test* /*suite*/) {}
    virtual void endTestSuite(const Test* /*suite*/) {}
    virtual void startTestRunner() {}
    virtual void endTestRunner() {}

    // Beyond RTF 2.x: every check with its outcome (a failed check also sends addFailure).
    virtual void addCheck(const Test* /*test*/, TestMessage /*msg*/, bool /*passed*/) {}
    // The test was not run; the message says why.
    virtual void addSkipped(const Test* /*test*/, TestMessage /*reason*/) {}
    // The test's process died of a signal; the message names it.
    virtual void addCrash(const Test* /*test*/, TestMessage /*msg*/) {}
    // The test ran past its time limit and was stopped.
    virtual void addTimeout(const Test* /*test*/, TestMessage /*msg*/) {}
    // The run was interrupted (Ctrl-C, SIGTERM) before or while this test ran.
    virtual void addInterrupted(const Test* /*test*/, TestMessage /*msg*/) {}
    // What the test (or a suite's fixtures) printed on stdout and stderr.
    virtual void addOutput(const Test* /*test*/, const std::string& /*text*/) {}
    // The running test now goes by `name` (a script calling setName). Listeners that show
    // names follow this, never the test object's name read later.
    virtual void renameTest(const Test* /*test*/, const std::string& /*name*/) {}
    // The test just ended failing and runs again (--retries); the message says which attempt.
    // Its next startTest/endTest are the same test, not another one.
    virtual void retryTest(const Test* /*test*/, TestMessage /*msg*/) {}
    // Repetition `index` of `count` of the test starts (count > 1: repetition="N",
    // --repetition N). The test's events up to its next startRepetition or endTest belong to it;
    // its id is repetitionId(test->getId(), index). By default it is the report
    // "repetition index/count", as RTF 2.x's listeners saw it.
    virtual void startRepetition(const Test* test, unsigned int index, unsigned int count);
    // The test measured something (Asserter::testMeasure); `passed`: within its limits. A
    // measurement outside them is followed by the addFailure that says so.
    virtual void addMeasurement(const Test* /*test*/, const Measurement& /*measurement*/,
                                bool /*passed*/) {}
    // The test attached a file, already copied into the run's attachments folder.
    virtual void addAttachment(const Test* /*test*/, const Attachment& /*attachment*/) {}
    // An event of a kind with no handler of its own above (ResultEvent::Kind::Probe, and kinds
    // added later until they get one): its word is toString(event.kind), the state it gives
    // the test stateOf(event.kind).
    virtual void addEvent(const Test* /*test*/, const ResultEvent& /*event*/) {}

    // Every event, as TestResult::publish sends it. The default is the one switch from an
    // event's kind to its named handler above. (Declared last, as addEvent: the virtuals of
    // RTF 2.x keep their places.)
    virtual void onEvent(const RunEvent& event);
};

}  // namespace robottestingframework
