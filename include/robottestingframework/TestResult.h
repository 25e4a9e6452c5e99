// The hub of a run: every event goes through it to all the registered listeners, in order.
#pragma once

#include <mutex>
#include <string>
#include <vector>

#include <robottestingframework/RunEvent.h>
#include <robottestingframework/Test.h>  // as in RTF 2.x
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestMessage.h>

namespace robottestingframework {

class Test;
class TestSuite;

class TestResult {
public:
    // Listeners are not owned; they must outlive the run.
    void addListener(TestListener* listener);
    void removeListener(TestListener* listener);

    // The one fan-out: hands `event` to every listener's onEvent, in order, as it is. The named
    // senders below make the event of their kind (cutting a message or detail longer than
    // 128 KiB, saying so) and publish it.
    void publish(const RunEvent& event);

    void addReport(const Test* test, TestMessage msg);
    void addError(const Test* test, TestMessage msg);
    void addFailure(const Test* test, TestMessage msg);
    void startTest(const Test* test);
    void endTest(const Test* test);
    void startTestSuite(const TestSuite* suite);
    void endTestSuite(const TestSuite* suite);
    void startTestRunner();
    void endTestRunner();

    void addCheck(const Test* test, TestMessage msg, bool passed);
    void addSkipped(const Test* test, TestMessage reason);
    void addCrash(const Test* test, TestMessage msg);
    void addTimeout(const Test* test, TestMessage msg);
    void addInterrupted(const Test* test, TestMessage msg);
    void addOutput(const Test* test, const std::string& text);
    void renameTest(const Test* test, const std::string& name);
    void retryTest(const Test* test, TestMessage msg);
    void startRepetition(const Test* test, unsigned int index, unsigned int count);
    void addMeasurement(const Test* test, const Measurement& measurement, bool passed);
    void addAttachment(const Test* test, const Attachment& attachment);

private:
    std::vector<TestListener*> listeners_;
    // Fixture watcher threads may report while the test thread does; events stay whole.
    std::recursive_mutex mutex_;
};

}  // namespace robottestingframework
