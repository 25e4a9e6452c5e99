// A group of tests sharing fixture managers. Runs the fixtures' set-up in order, each test
// (checking the fixtures before it), then the fixtures' tear-down in reverse order.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <robottestingframework/FixtureEvents.h>
#include <robottestingframework/FixtureManager.h>  // with TestResult.h, as in RTF 2.x
#include <robottestingframework/Test.h>
#include <robottestingframework/TestGate.h>
#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestStatus.h>

namespace robottestingframework {

class FixtureManager;
class TestResult;
class TestListener;

class TestSuite : public Test, public FixtureEvents {
public:
    explicit TestSuite(std::string name);
    ~TestSuite() override;

    // Tests and fixture managers are not owned.
    void addTest(Test* test);
    void removeTest(Test* test);
    void reset();
    void addFixtureManager(FixtureManager* manager);
    std::size_t size() const { return tests_.size(); }
    const std::vector<Test*>& tests() const { return tests_; }

    void run(TestResult& result) override;
    void interrupt() override;
    bool succeeded() const override;
    void fixtureCollapsed(TestMessage reason) override;
    // Kept until the fixture's tearDown returns, then reported as a failed record of its own.
    bool fixtureCheckFailed(const std::string& name, const TestMessage& failure,
                            const Attachment* attachment) override;

    // The tests after the current one are skipped with `reason` (a critical error).
    void skipRemaining(const TestMessage& reason);
    // The reason the fixtures failed or collapsed, empty when they did not.
    TestMessage fixtureFailure() const;

    // Beyond RTF 2.x: consulted before each test; a test it refuses is reported skipped.
    void setGate(TestGate* gate) { gate_ = gate; }
    // Reports the whole suite as not run: every test skipped (or interrupted) with `reason`.
    void reportNotRun(TestResult& result, const TestMessage& reason, bool interrupted);

private:
    bool setupFixtures(TestResult& result);
    void tearDownFixtures(TestResult& result, std::size_t count);
    bool checkFixtures(TestResult& result);
    void reportFixtureChecks(TestResult& result);
    void reportRemaining(TestResult& result, std::size_t from, const TestMessage& reason,
                         bool interrupted);

    std::vector<Test*> tests_;
    std::vector<FixtureManager*> fixtures_;
    TestGate* gate_ = nullptr;
    bool successful_ = true;
    std::atomic<bool> interrupted_{false};
    std::atomic<bool> collapsed_{false};
    mutable std::mutex mutex_;
    Test* current_ = nullptr;
    TestMessage failure_;
    TestMessage skipReason_;
    bool skipRest_ = false;
    // Failed checks of a fixture's tear-down (fixtureCheckFailed), waiting to be reported, and
    // the records they became (alive as long as the run's listeners may name them).
    struct FixtureCheck {
        std::string name;
        TestMessage failure;
        bool attached = false;
        Attachment attachment;
    };
    std::vector<FixtureCheck> pendingChecks_;
    std::vector<std::unique_ptr<Test>> checkRecords_;
};

}  // namespace robottestingframework
