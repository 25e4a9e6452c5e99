#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestSuite.h>

namespace robottestingframework {

void TestListener::onEvent(const RunEvent& event) {
    using Kind = ResultEvent::Kind;
    const ResultEvent& data = event.data;
    const Test* test = event.test;
    switch (data.kind) {
        case Kind::StartRunner:
            startTestRunner();
            break;
        case Kind::EndRunner:
            endTestRunner();
            break;
        case Kind::StartSuite:
            startTestSuite(event.suite);
            break;
        case Kind::EndSuite:
            endTestSuite(event.suite);
            break;
        case Kind::StartTest:
            startTest(test);
            break;
        case Kind::EndTest:
            endTest(test);
            break;
        case Kind::Report:
            addReport(test, data.message);
            break;
        case Kind::Check:
            addCheck(test, data.message, data.passed);
            break;
        case Kind::Failure:
            addFailure(test, data.message);
            break;
        case Kind::Error:
            addError(test, data.message);
            break;
        case Kind::Skipped:
            addSkipped(test, data.message);
            break;
        case Kind::Crash:
            addCrash(test, data.message);
            break;
        case Kind::Timeout:
            addTimeout(test, data.message);
            break;
        case Kind::Interrupted:
            addInterrupted(test, data.message);
            break;
        case Kind::Output:
            addOutput(test, data.message.getMessage());
            break;
        case Kind::Rename:
            renameTest(test, data.message.getMessage());
            break;
        case Kind::Retry:
            retryTest(test, data.message);
            break;
        case Kind::Repetition:
            startRepetition(test, data.repetition, data.repetitions);
            break;
        // Without what it carries (a broken worker's record), it is an event like any other.
        case Kind::Measurement:
            if (data.measurement) {
                addMeasurement(test, *data.measurement, data.passed);
            } else {
                addEvent(test, data);
            }
            break;
        case Kind::Attachment:
            if (data.attachment) {
                addAttachment(test, *data.attachment);
            } else {
                addEvent(test, data);
            }
            break;
        case Kind::Probe:
            addEvent(test, data);
            break;
        // About no test (`test` is nullptr): a listener that does not show worlds ignores it.
        case Kind::World:
            addEvent(test, data);
            break;
    }
}

void TestListener::startTestSuite(const TestSuite* suite) {
    startTestSuite(static_cast<const Test*>(suite));
}

void TestListener::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    addReport(test, repetitionMessage(index, count));
}

void TestListener::endTestSuite(const TestSuite* suite) {
    endTestSuite(static_cast<const Test*>(suite));
}

}  // namespace robottestingframework
