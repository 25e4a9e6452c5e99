// The base of everything that can run and report to a TestResult: test cases and suites.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <utility>

#include <robottestingframework/TestMessage.h>

namespace robottestingframework {

class TestResult;

class Test {
public:
    explicit Test(std::string name, std::string description = "");
    virtual ~Test();
    Test(const Test&) = delete;
    Test& operator=(const Test&) = delete;

    // While the test runs (TestCase::run), a new name is also an event: its TestResult tells
    // the listeners (renameTest), which follow it by id instead of reading the name later.
    void setName(std::string name);
    const std::string getName() const { return name_; }
    void setDescription(std::string description) { description_ = std::move(description); }
    const std::string getDescription() const { return description_; }

    // Beyond RTF 2.x: the test's id in its suite (README: "Test ids"), which the runner's plan
    // gives and every report names the test by; the name above is then only shown beside it.
    // Empty (a test used without a plan): reports name the test by its name.
    void setKey(std::string key) { key_ = std::move(key); }
    const std::string& getKey() const { return key_; }

    // Beyond RTF 2.x: a number unique in the process, which every event about the test carries
    // and listeners key by. The runner's plan gives it; a test used without a plan gets it the
    // first time it is asked for.
    std::uint64_t getId() const;
    // The result a running test's renames go to (nullptr: none). TestCase::run sets it.
    void reportRenamesTo(TestResult* result) { renames_ = result; }

    virtual void run(TestResult& result) = 0;
    // Asks a running test to stop as soon as it can. May be called from another thread.
    virtual void interrupt() {}
    virtual bool succeeded() const = 0;

    // Beyond RTF 2.x: a test that raised a critical error (ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL)
    // carries it here; its suite then skips the tests after it with this reason.
    bool hasCriticalError() const { return critical_; }
    const TestMessage& getCriticalError() const { return criticalError_; }
    void setCriticalError(const TestMessage& reason) {
        critical_ = true;
        criticalError_ = reason;
    }
    void clearCriticalError() { critical_ = false; }

private:
    std::string name_;
    std::string description_;
    std::string key_;
    bool critical_ = false;
    TestMessage criticalError_;
    mutable std::atomic<std::uint64_t> id_{0};
    TestResult* renames_ = nullptr;
};

}  // namespace robottestingframework
