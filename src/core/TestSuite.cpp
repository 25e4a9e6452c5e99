#include <robottestingframework/TestSuite.h>

#include <algorithm>
#include <exception>
#include <mutex>
#include <string>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResult.h>

#include "core/guarded_call.h"
#include "core/not_run_reasons.h"

namespace robottestingframework {

namespace {

std::string fixtureName(const FixtureManager* fixture, std::size_t index) {
    const std::string name = fixture->getName();
    return name.empty() ? "#" + std::to_string(index + 1) : name;
}

// The last report made about `suite` while it listens: what a fixture said before its setup
// returned false is the reason its tests are skipped.
class LastReport : public TestListener {
public:
    LastReport(TestResult& result, const Test* suite) : result_(result), suite_(suite) {
        result_.addListener(this);
    }
    ~LastReport() override { result_.removeListener(this); }
    void addReport(const Test* test, TestMessage message) override {
        if (test == suite_) {
            std::lock_guard<std::mutex> lock(mutex_);
            last_ = message.toString();
        }
    }
    std::string text() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return last_;
    }

private:
    TestResult& result_;
    const Test* suite_;
    mutable std::mutex mutex_;
    std::string last_;
};

// A failed check of a fixture's tear-down (a process that did not stop cleanly), reported as a
// test of its own: every report shows it as a record of its own.
class FixtureCheckRecord : public Test {
public:
    explicit FixtureCheckRecord(const std::string& name) : Test(name) {}
    void run(TestResult& /*result*/) override {}
    bool succeeded() const override { return false; }
};

}  // namespace

TestSuite::TestSuite(std::string name) : Test(std::move(name)) {}

TestSuite::~TestSuite() = default;

void TestSuite::addTest(Test* test) {
    if (test != nullptr) {
        tests_.push_back(test);
    }
}

void TestSuite::removeTest(Test* test) {
    tests_.erase(std::remove(tests_.begin(), tests_.end(), test), tests_.end());
}

void TestSuite::reset() {
    tests_.clear();
    fixtures_.clear();
}

void TestSuite::addFixtureManager(FixtureManager* manager) {
    if (manager != nullptr) {
        // At once, as RTF 2.x did: a fixture may report a collapse before the suite runs.
        if (manager->getDispatcher() == nullptr) {
            manager->setDispatcher(this);
        }
        fixtures_.push_back(manager);
    }
}

bool TestSuite::succeeded() const {
    return successful_;
}

void TestSuite::interrupt() {
    interrupted_ = true;
    std::lock_guard<std::mutex> lock(mutex_);
    if (current_ != nullptr) {
        current_->interrupt();
    }
}

void TestSuite::fixtureCollapsed(TestMessage reason) {
    // Only flags and interrupts: the suite reports the collapse on its own thread, between
    // tests, so events of the running test are not torn apart.
    std::lock_guard<std::mutex> lock(mutex_);
    if (!collapsed_) {
        failure_ = reason;
        collapsed_ = true;
    }
    if (current_ != nullptr) {
        current_->interrupt();
    }
}

void TestSuite::skipRemaining(const TestMessage& reason) {
    std::lock_guard<std::mutex> lock(mutex_);
    skipRest_ = true;
    skipReason_ = reason;
}

TestMessage TestSuite::fixtureFailure() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return failure_;
}

bool TestSuite::setupFixtures(TestResult& result) {
    for (std::size_t i = 0; i < fixtures_.size(); ++i) {
        FixtureManager* fixture = fixtures_[i];
        fixture->setResult(&result, this);
        if (fixture->getDispatcher() == nullptr) {
            fixture->setDispatcher(this);
        }
        bool up = false;
        std::string why;
        LastReport said(result, this);
        if (guardedCall([&] { up = fixture->setup(); }, why) && !up) {
            why = "setup returned false";
            if (!said.text().empty()) {
                why += " after reporting: " + said.text();
            }
        }
        if (!up) {
            const TestMessage failure("fixture " + fixtureName(fixture, i) + " failed: " + why);
            {
                std::lock_guard<std::mutex> lock(mutex_);
                failure_ = failure;
            }
            successful_ = false;
            result.addError(this, failure);
            tearDownFixtures(result, i);
            return false;
        }
    }
    return true;
}

bool TestSuite::fixtureCheckFailed(const std::string& name, const TestMessage& failure,
                                   const Attachment* attachment) {
    FixtureCheck check;
    check.name = name;
    check.failure = failure;
    if (attachment != nullptr) {
        check.attached = true;
        check.attachment = *attachment;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    pendingChecks_.push_back(std::move(check));
    return true;
}

void TestSuite::reportFixtureChecks(TestResult& result) {
    std::vector<FixtureCheck> checks;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        checks.swap(pendingChecks_);
    }
    for (const FixtureCheck& check : checks) {
        successful_ = false;
        checkRecords_.push_back(std::make_unique<FixtureCheckRecord>(check.name));
        const Test* record = checkRecords_.back().get();
        result.startTest(record);
        result.addFailure(record, check.failure);
        if (check.attached) {
            result.addAttachment(record, check.attachment);
        }
        result.endTest(record);
    }
}

void TestSuite::tearDownFixtures(TestResult& result, std::size_t count) {
    for (std::size_t k = count; k > 0; --k) {
        FixtureManager* fixture = fixtures_[k - 1];
        std::string why;
        const bool done = guardedCall([fixture] { fixture->tearDown(); }, why);
        reportFixtureChecks(result);
        if (!done) {
            successful_ = false;
            result.addError(this, TestMessage("fixture " + fixtureName(fixture, k - 1) +
                                              " tearDown failed: " + why));
        }
    }
}

bool TestSuite::checkFixtures(TestResult& /*result*/) {
    for (std::size_t i = 0; i < fixtures_.size(); ++i) {
        FixtureManager* fixture = fixtures_[i];
        bool ok = false;
        std::string why;
        if (guardedCall([&] { ok = fixture->check(); }, why) && !ok) {
            why = "check failed";
        }
        if (!ok) {
            fixtureCollapsed(TestMessage("fixture " + fixtureName(fixture, i) + ": " + why));
            return false;
        }
    }
    return true;
}

void TestSuite::reportRemaining(TestResult& result, std::size_t from, const TestMessage& reason,
                                bool interrupted) {
    for (std::size_t i = from; i < tests_.size(); ++i) {
        Test* test = tests_[i];
        if (auto* suite = dynamic_cast<TestSuite*>(test)) {
            suite->reportNotRun(result, reason, interrupted);
            continue;
        }
        result.startTest(test);
        if (interrupted) {
            result.addInterrupted(test, reason);
        } else {
            result.addSkipped(test, reason);
        }
        result.endTest(test);
    }
}

void TestSuite::reportNotRun(TestResult& result, const TestMessage& reason, bool interrupted) {
    successful_ = !interrupted;
    result.startTestSuite(this);
    reportRemaining(result, 0, reason, interrupted);
    result.endTestSuite(this);
}

void TestSuite::run(TestResult& result) {
    successful_ = true;
    clearCriticalError();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        failure_.clear();
        skipReason_.clear();
        skipRest_ = false;
        collapsed_ = false;
        pendingChecks_.clear();
    }
    result.startTestSuite(this);

    bool collapseReported = false;
    auto reportCollapse = [&] {
        if (!collapsed_ || collapseReported) {
            return;
        }
        collapseReported = true;
        successful_ = false;
        const TestMessage reason = fixtureFailure();
        result.addError(this,
                        TestMessage("fixture collapsed: " + reason.getMessage(), reason.getDetail(),
                                    reason.getSourceFileName(), reason.getSourceLineNumber()));
    };
    // Reports tests [i, end) as not run when something stops the suite; true if it did.
    auto stopped = [&](std::size_t i) {
        if (interrupted_) {
            successful_ = false;
            reportRemaining(result, i, TestMessage(notrun::interrupted), true);
            return true;
        }
        if (collapsed_) {
            reportCollapse();
            // The whole reason is the suite's error, said once; each test refers to it.
            reportRemaining(result, i,
                            notrun::fixtureReason(notrun::fixtureCollapsed, fixtureFailure()),
                            false);
            return true;
        }
        TestMessage reason;
        bool skip = false;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            skip = skipRest_;
            reason = skipReason_;
        }
        if (skip) {
            reportRemaining(result, i, reason, false);
        }
        return skip;
    };

    if (interrupted_) {
        stopped(0);
    } else if (!setupFixtures(result)) {
        // A set-up cut short by Ctrl-C: the tests were interrupted, not skipped for a reason
        // of their own.
        if (interrupted_) {
            successful_ = false;
            reportRemaining(result, 0, TestMessage(notrun::interrupted), true);
        } else {
            // The whole reason is the suite's error, said once; each test refers to it.
            reportRemaining(result, 0,
                            notrun::fixtureReason(notrun::fixtureFailed, fixtureFailure()), false);
        }
    } else {
        for (std::size_t i = 0; i < tests_.size(); ++i) {
            Test* test = tests_[i];
            if (stopped(i)) {
                break;
            }
            TestMessage reason;
            if (gate_ != nullptr && gate_->skip(test, reason)) {
                if (auto* suite = dynamic_cast<TestSuite*>(test)) {
                    suite->reportNotRun(result, reason, false);
                } else {
                    result.startTest(test);
                    result.addSkipped(test, reason);
                    result.endTest(test);
                }
                continue;
            }
            if (!checkFixtures(result) && stopped(i)) {
                break;
            }
            bool started = false;
            {
                // Checked under the lock interrupt() and fixtureCollapsed() take: an interrupt
                // or a collapse is either seen here or reaches the test through current_.
                std::lock_guard<std::mutex> lock(mutex_);
                if (!interrupted_ && !collapsed_) {
                    current_ = test;
                    started = true;
                }
            }
            if (!started) {
                stopped(i);
                break;
            }
            if (auto* suite = dynamic_cast<TestSuite*>(test)) {
                if (gate_ != nullptr) {
                    suite->setGate(gate_);
                }
            }
            test->run(result);
            {
                std::lock_guard<std::mutex> lock(mutex_);
                current_ = nullptr;
            }
            if (!test->succeeded()) {
                successful_ = false;
            }
            reportCollapse();
            if (test->hasCriticalError()) {
                skipRemaining(TestMessage("critical error in " + test->getName() + ": " +
                                          test->getCriticalError().toString()));
            }
        }
        tearDownFixtures(result, fixtures_.size());
        reportCollapse();
    }

    result.endTestSuite(this);
    interrupted_ = false;
}

}  // namespace robottestingframework
