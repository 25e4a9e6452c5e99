// Keeps every event of a run, in order, and the counts and per-test records outputters need.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestStatus.h>

namespace robottestingframework {

struct TestRecord;

// One measurement of a test as the records keep it: issue 22's 10 000 tests of three
// measurements keep 30 000 of these, so it holds no text of its own (its name and unit are the
// collector's one copy of that pair, shared by every measurement naming it) and no event.
struct MeasurementRecord {
    struct Label {
        std::string name;
        std::string unit;
    };
    std::shared_ptr<const Label> label;  // never null in a collector's records
    double value = 0;
    double low = 0;               // when hasLow
    double high = 0;              // when hasHigh
    double time = 0;              // seconds since the collector started, when it was received
    unsigned int repetition = 0;  // as ResultEvent::repetition
    std::uint32_t position = 0;   // how many of its test's kept events came before it
    bool hasLow = false;
    bool hasHigh = false;
    bool passed = true;  // within its limits

    const std::string& name() const;
    const std::string& unit() const;
    Measurement measurement() const;
    // The Measurement event it was, about `test` (the message describeMeasurement's).
    ResultEvent event(const TestRecord& test) const;
};

// A test's (or an attempt's) measurements, in order: one pointer while there are none. Most
// tests measure nothing, and a run keeps a record per test (issue 23: 10 000 tests in process),
// so an empty list costs 8 bytes instead of an empty vector's 24.
class MeasurementList {
public:
    MeasurementList() = default;
    MeasurementList(const MeasurementList& other);
    MeasurementList& operator=(const MeasurementList& other);
    MeasurementList(MeasurementList&&) noexcept = default;
    MeasurementList& operator=(MeasurementList&&) noexcept = default;
    ~MeasurementList() = default;

    bool empty() const { return items_ == nullptr || items_->empty(); }
    std::size_t size() const { return items_ == nullptr ? 0 : items_->size(); }
    const MeasurementRecord& operator[](std::size_t i) const { return (*items_)[i]; }
    MeasurementRecord& operator[](std::size_t i) { return (*items_)[i]; }
    const MeasurementRecord* begin() const { return items_ == nullptr ? nullptr : items_->data(); }
    const MeasurementRecord* end() const { return begin() + size(); }
    MeasurementRecord* begin() { return items_ == nullptr ? nullptr : items_->data(); }
    MeasurementRecord* end() { return begin() + size(); }
    void push_back(MeasurementRecord record);
    void clear() { items_.reset(); }

private:
    std::unique_ptr<std::vector<MeasurementRecord>> items_;
};

// Hands out one label per distinct (name, unit): what the records' measurements share.
class MeasurementLabels {
public:
    std::shared_ptr<const MeasurementRecord::Label> intern(const std::string& name,
                                                           const std::string& unit);
    void clear() { labels_.clear(); }

private:
    std::map<std::pair<std::string, std::string>, std::shared_ptr<const MeasurementRecord::Label>>
        labels_;
};

// One failed attempt of a test that ran again (--retries).
struct TestAttempt {
    TestStatus status = TestStatus::Failed;
    TestMessage message;  // what decided its state, if anything did
    std::string output;   // what it printed
    double duration = 0;  // seconds
    // Its measurements: the HTML report plots a measurement across attempts.
    MeasurementList measurements;
};

// One repetition of a test that runs several times (repetition="N"); its id is
// repetitionId(test id, index).
struct TestRepetition {
    unsigned int index = 0;  // 1..count
    unsigned int count = 0;
    TestStatus status = TestStatus::Passed;  // the highest state its events gave
    double start = 0;                        // seconds since the collector started
    double duration = 0;                     // seconds
};

// One test as the outputs show it.
struct TestRecord {
    std::uint64_t id = 0;  // the test's Test::getId()
    std::string key;       // its id in its suite (Test::getKey()); empty without a plan
    std::string name;      // the name it gives itself, shown beside the key
    std::string description;
    TestStatus status = TestStatus::Passed;
    double start = 0;     // seconds since the collector started
    double duration = 0;  // seconds
    // Its reports, checks, failures, errors, ... in order; its measurements are kept apart.
    std::vector<ResultEvent> events;
    MeasurementList measurements;  // in order, each knowing its place in events
    std::string output;            // what it printed
    // The earlier failed attempts, oldest first, when the test ran again (--retries); the
    // state, events and output above are the last attempt's, start and duration all of them.
    std::vector<TestAttempt> attempts;
    // Its repetitions in order (of the last attempt), when it runs several times; else empty.
    std::vector<TestRepetition> repetitions;
    // What every report names the test by: its key, else (a test run without a plan) its name.
    const std::string& reportName() const { return key.empty() ? name : key; }
    // The name to show beside reportName(): its own name when that differs and is not an
    // absolute path (the name a loader gives a script it loaded); else empty.
    std::string shownName() const {
        return key.empty() || name == key || (!name.empty() && name[0] == '/') ? std::string()
                                                                               : name;
    }
    // Its events in arrival order with its measurements among them as Measurement events:
    // `events` itself when it measured nothing, else `scratch` filled with them.
    const std::vector<ResultEvent>& eventsInOrder(std::vector<ResultEvent>& scratch) const;
    // `measured` (its own or an attempt's) as Measurement events, in order.
    std::vector<ResultEvent> measurementEvents(const MeasurementList& measured) const;
    // The message that decided the state (first failure, error, crash, ...), if any.
    const ResultEvent* reason() const;
};

// One suite as the outputs show it. Tests run outside any suite go to an unnamed suite.
struct SuiteRecord {
    std::uint64_t id = 0;  // the suite's Test::getId(); 0 for tests run outside a suite
    std::string name;
    std::string description;
    double start = 0;
    double duration = 0;
    std::vector<TestRecord> tests;
    std::vector<ResultEvent> events;  // the suite's own: fixture reports, failures, collapse
    std::string output;               // what its fixtures printed
    bool fixtureFailed = false;
    bool succeeded() const;
};

// A world shared by suites (<fixture scope="run">), from its ResultEvent::Kind::World events:
// each time in seconds since the collector started, -1 when it did not happen.
struct WorldRecord {
    std::string name;
    std::string users;  // "3 suites"
    double start = -1;
    double ready = -1;
    double stop = -1;
    double failed = -1;  // it failed to start or collapsed
    std::string reason;  // why
};

class TestResultCollector : public TestListener {
public:
    TestResultCollector();
    ~TestResultCollector() override;

    // Counts of tests (not suites). failedCount() counts every state that fails a run.
    // As in RTF 2.x, the tests of a suite whose fixture failed (set up or collapsed) are not
    // run and not counted; their records are kept (skipped, with the fixture's reason). See
    // setCountTestsNotRun.
    std::size_t testCount() const;
    std::size_t passedCount() const;
    std::size_t failedCount() const;
    std::size_t skippedCount() const;
    std::size_t countOf(TestStatus status) const;
    std::size_t suiteCount() const;
    std::size_t passedSuiteCount() const;
    std::size_t failedSuiteCount() const;
    // Beyond RTF 2.x: the suites whose fixture failed (set up, tear down or collapse), each
    // once; the closing line counts them as failed, so it agrees with the exit status.
    std::size_t failedFixtureCount() const;
    // Forgets everything collected (events, records, counts) and restarts the clock, so one
    // collector can serve several runs.
    void reset();

    // Every event in arrival order.
    const std::vector<ResultEvent>& getResults() const { return events_; }
    // Suites in order, with their tests.
    const std::vector<SuiteRecord>& suites() const { return suites_; }
    // The shared worlds of the run, in the order they started.
    const std::vector<WorldRecord>& worlds() const { return worlds_; }
    // Wall time from startTestRunner to endTestRunner (or to now while running).
    double duration() const;
    // The calendar time the collector was made; event times count from it.
    std::chrono::system_clock::time_point startedAt() const { return wallOrigin_; }
    // Drops events and records (counts stay). For runs with very many tests.
    void setKeepEvents(bool keep) { keepEvents_ = keep; }
    // Keeps the records (what the outputs need) but not the arrival-order list of
    // getResults(), which then stays empty. Saves memory on large runs.
    void setKeepEventLog(bool keep) { keepLog_ = keep; }
    // Keeps check events in the records only when true (the outputs show them only verbose).
    void setKeepChecks(bool keep) { keepChecks_ = keep; }
    // Beyond RTF 2.x: true counts the tests a failed fixture kept from running as skipped
    // tests too (the runner's reports and console do: they list them).
    void setCountTestsNotRun(bool count) { countNotRun_ = count; }
    // Keeps at most `bytes` of what the tests printed over the whole run (0: no limit, the
    // default): once that is spent, each test that ends keeps the last 4 KiB of its output
    // only, saying so. Bounds the runner's memory on runs of many talkative tests.
    void setOutputBudget(std::size_t bytes) { outputBudget_ = bytes; }

    // Ends the tests and suites still open, each open test interrupted with `why`: for the
    // outputs of a run cut short. The collector must receive no more events meanwhile.
    void interruptOpen(const TestMessage& why);

    void addReport(const Test* test, TestMessage msg) override;
    void addError(const Test* test, TestMessage msg) override;
    void addFailure(const Test* test, TestMessage msg) override;
    void startTest(const Test* test) override;
    void endTest(const Test* test) override;
    void startTestSuite(const TestSuite* suite) override;
    void endTestSuite(const TestSuite* suite) override;
    void startTestRunner() override;
    void endTestRunner() override;
    void addCheck(const Test* test, TestMessage msg, bool passed) override;
    void addSkipped(const Test* test, TestMessage reason) override;
    void addCrash(const Test* test, TestMessage msg) override;
    void addTimeout(const Test* test, TestMessage msg) override;
    void addInterrupted(const Test* test, TestMessage msg) override;
    void addOutput(const Test* test, const std::string& text) override;
    void renameTest(const Test* test, const std::string& name) override;
    void retryTest(const Test* test, TestMessage msg) override;
    void startRepetition(const Test* test, unsigned int index, unsigned int count) override;
    void addMeasurement(const Test* test, const Measurement& measurement, bool passed) override;
    void addAttachment(const Test* test, const Attachment& attachment) override;
    void addEvent(const Test* test, const ResultEvent& event) override;
    // Hands the event to the named handlers (a subclass may override them, as in RTF 2.x), with
    // the time it happened at hand.
    void onEvent(const RunEvent& event) override;
    // For a listener that keeps a collector of its own and calls its named handlers itself
    // (ConsoleListener): what they record is timed when `event` happened, as onEvent times
    // it. Returns the event timed so before, to give back after (nullptr: the time now).
    const RunEvent* timeAs(const RunEvent* event);

private:
    // A test between its startTest and endTest: where its record is. Found by id, never by
    // pointer or name (a stand-in may be reused; two tests may share a name).
    struct OpenTest {
        std::uint64_t id;
        const Test* test;  // only to end it when the run is cut short
        std::size_t suite;
        std::size_t index;
        unsigned int repetition = 0;  // the one its events now belong to; 0: runs once
    };
    static constexpr std::size_t none = static_cast<std::size_t>(-1);

    double now() const;
    // Keeps `made` (made by name, src/core/events.h), about `test`, where it belongs (its record,
    // else the open suite's), moving only what it keeps: a passed check it does not keep is
    // dropped unseen. `measurement`: what a measurement carries (the event's own is not read);
    // a test's goes to its record as a MeasurementRecord (the event log and a suite keep the
    // event).
    void record(const Test* test, ResultEvent&& made, const Measurement* measurement = nullptr);
    OpenTest* findOpen(const Test* test);
    SuiteRecord& currentSuite();
    // Cuts a test's output to its tail once the run's output budget is spent.
    void keepWithinBudget(std::string& output);

    void recordWorld(const ResultEvent& event);
    std::vector<WorldRecord> worlds_;
    std::chrono::steady_clock::time_point origin_;
    // The event onEvent is handing to the named handlers, while it does (else null): when it
    // happened.
    const RunEvent* delivering_ = nullptr;
    MeasurementLabels labels_;  // the names and units of the records' measurements
    std::chrono::system_clock::time_point wallOrigin_;
    double start_ = 0;
    double end_ = -1;
    bool keepEvents_ = true;
    bool keepLog_ = true;
    bool keepChecks_ = true;
    bool countNotRun_ = false;
    std::size_t outputBudget_ = 0;
    std::size_t outputKept_ = 0;  // bytes of test output the records hold
    std::vector<ResultEvent> events_;
    std::vector<SuiteRecord> suites_;
    // A suite between its startTestSuite and endTestSuite; `failed` survives dropped records.
    struct OpenSuite {
        std::size_t index;
        std::size_t failed;  // how many of its tests failed (a retry takes one back)
    };
    std::vector<OpenSuite> openSuites_;           // innermost last
    std::vector<OpenTest> openTests_;             // innermost last
    OpenTest lastEnded_{0, nullptr, none, none};  // the record a retry goes on with
    OpenTest retrying_{0, nullptr, none, none};   // the record the next startTest reopens
    std::size_t looseSuite_ = none;               // the unnamed record of tests run outside a suite
    // Counts survive setKeepEvents(false), which drops finished records.
    std::size_t counts_[8] = {};
    std::size_t suitesRun_ = 0;
    std::size_t suitesFailed_ = 0;
    std::size_t fixturesFailed_ = 0;
};

}  // namespace robottestingframework
