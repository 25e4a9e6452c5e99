// What a suite running on a thread of its own reports, kept in order until the scheduler's
// thread hands it on: the listeners of the run (console, collector, reporters, web page) get
// every event from that one thread, each suite's events in the order they happened.
#pragma once

#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResult.h>

namespace robottestingframework {
namespace runner {

class SuiteEvents : public TestListener {
public:
    using Event = std::function<void(TestListener&)>;

    // `wake`: called (on the reporting thread) after each event, to wake the scheduler.
    explicit SuiteEvents(std::function<void()> wake) : wake_(std::move(wake)) {}

    // The events since the last call, oldest first.
    std::vector<Event> take();
    // From now on each event goes straight to `result` as it comes (nullptr: kept again), for
    // a suite run on the scheduler's own thread.
    void passTo(TestResult* result) { direct_ = result; }

    void addReport(const Test* test, TestMessage msg) override;
    void addError(const Test* test, TestMessage msg) override;
    void addFailure(const Test* test, TestMessage msg) override;
    void startTest(const Test* test) override;
    void endTest(const Test* test) override;
    void startTestSuite(const TestSuite* suite) override;
    void endTestSuite(const TestSuite* suite) override;
    void addCheck(const Test* test, TestMessage msg, bool passed) override;
    void addSkipped(const Test* test, TestMessage reason) override;
    void addCrash(const Test* test, TestMessage msg) override;
    void addTimeout(const Test* test, TestMessage msg) override;
    void addInterrupted(const Test* test, TestMessage msg) override;
    void addOutput(const Test* test, const std::string& text) override;
    void renameTest(const Test* test, const std::string& name) override;
    void retryTest(const Test* test, TestMessage msg) override;
    void startRepetition(const Test* test, unsigned int index, unsigned int count) override;

private:
    void add(Event event);

    std::function<void()> wake_;
    TestResult* direct_ = nullptr;
    std::mutex mutex_;
    std::vector<Event> events_;
};

// Hands `event` to every listener of `result`, as if it had been reported there.
void replay(const SuiteEvents::Event& event, TestResult& result);

}  // namespace runner
}  // namespace robottestingframework
