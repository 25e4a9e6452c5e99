#include "runner/schedule/suite_events.h"

#include <robottestingframework/TestSuite.h>

namespace robottestingframework {
namespace runner {

namespace {

// The run's listeners behind one listener, for replay().
class ToResult : public TestListener {
public:
    explicit ToResult(TestResult& result) : result_(result) {}
    void addReport(const Test* test, TestMessage msg) override { result_.addReport(test, msg); }
    void addError(const Test* test, TestMessage msg) override { result_.addError(test, msg); }
    void addFailure(const Test* test, TestMessage msg) override { result_.addFailure(test, msg); }
    void startTest(const Test* test) override { result_.startTest(test); }
    void endTest(const Test* test) override { result_.endTest(test); }
    void startTestSuite(const TestSuite* suite) override { result_.startTestSuite(suite); }
    void endTestSuite(const TestSuite* suite) override { result_.endTestSuite(suite); }
    void addCheck(const Test* test, TestMessage msg, bool passed) override {
        result_.addCheck(test, msg, passed);
    }
    void addSkipped(const Test* test, TestMessage reason) override {
        result_.addSkipped(test, reason);
    }
    void addCrash(const Test* test, TestMessage msg) override { result_.addCrash(test, msg); }
    void addTimeout(const Test* test, TestMessage msg) override { result_.addTimeout(test, msg); }
    void addInterrupted(const Test* test, TestMessage msg) override {
        result_.addInterrupted(test, msg);
    }
    void addOutput(const Test* test, const std::string& text) override {
        result_.addOutput(test, text);
    }
    void renameTest(const Test* test, const std::string& name) override {
        result_.renameTest(test, name);
    }
    void retryTest(const Test* test, TestMessage msg) override { result_.retryTest(test, msg); }
    void startRepetition(const Test* test, unsigned int index, unsigned int count) override {
        result_.startRepetition(test, index, count);
    }

private:
    TestResult& result_;
};

}  // namespace

void replay(const SuiteEvents::Event& event, TestResult& result) {
    ToResult target(result);
    event(target);
}

std::vector<SuiteEvents::Event> SuiteEvents::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Event> taken;
    taken.swap(events_);
    return taken;
}

void SuiteEvents::add(Event event) {
    if (direct_ != nullptr) {
        replay(event, *direct_);
        return;
    }
    bool first = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        first = events_.empty();
        events_.push_back(std::move(event));
    }
    // One wake-up per batch: the scheduler takes them all at once.
    if (first && wake_) {
        wake_();
    }
}

void SuiteEvents::addReport(const Test* test, TestMessage msg) {
    add([=](TestListener& to) { to.addReport(test, msg); });
}
void SuiteEvents::addError(const Test* test, TestMessage msg) {
    add([=](TestListener& to) { to.addError(test, msg); });
}
void SuiteEvents::addFailure(const Test* test, TestMessage msg) {
    add([=](TestListener& to) { to.addFailure(test, msg); });
}
void SuiteEvents::startTest(const Test* test) {
    add([=](TestListener& to) { to.startTest(test); });
}
void SuiteEvents::endTest(const Test* test) {
    add([=](TestListener& to) { to.endTest(test); });
}
void SuiteEvents::startTestSuite(const TestSuite* suite) {
    add([=](TestListener& to) { to.startTestSuite(suite); });
}
void SuiteEvents::endTestSuite(const TestSuite* suite) {
    add([=](TestListener& to) { to.endTestSuite(suite); });
}
void SuiteEvents::addCheck(const Test* test, TestMessage msg, bool passed) {
    add([=](TestListener& to) { to.addCheck(test, msg, passed); });
}
void SuiteEvents::addSkipped(const Test* test, TestMessage reason) {
    add([=](TestListener& to) { to.addSkipped(test, reason); });
}
void SuiteEvents::addCrash(const Test* test, TestMessage msg) {
    add([=](TestListener& to) { to.addCrash(test, msg); });
}
void SuiteEvents::addTimeout(const Test* test, TestMessage msg) {
    add([=](TestListener& to) { to.addTimeout(test, msg); });
}
void SuiteEvents::addInterrupted(const Test* test, TestMessage msg) {
    add([=](TestListener& to) { to.addInterrupted(test, msg); });
}
void SuiteEvents::addOutput(const Test* test, const std::string& text) {
    add([=](TestListener& to) { to.addOutput(test, text); });
}
void SuiteEvents::renameTest(const Test* test, const std::string& name) {
    add([=](TestListener& to) { to.renameTest(test, name); });
}
void SuiteEvents::retryTest(const Test* test, TestMessage msg) {
    add([=](TestListener& to) { to.retryTest(test, msg); });
}
void SuiteEvents::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    add([=](TestListener& to) { to.startRepetition(test, index, count); });
}

}  // namespace runner
}  // namespace robottestingframework
