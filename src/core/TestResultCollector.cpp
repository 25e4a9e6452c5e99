#include <robottestingframework/TestResultCollector.h>

#include <algorithm>
#include <memory>
#include <set>
#include <utility>

#include <robottestingframework/RunEvent.h>
#include <robottestingframework/Test.h>
#include <robottestingframework/TestSuite.h>

#include "core/events.h"

namespace robottestingframework {

namespace {

// `event` about `test` (its name and id), received at `time`.
ResultEvent stamped(ResultEvent event, const Test* test, double time) {
    if (test != nullptr) {
        event.testName = test->getName();
        event.testId = test->getId();
    }
    event.time = time;
    return event;
}

}  // namespace

const std::string& MeasurementRecord::name() const {
    return label->name;
}

const std::string& MeasurementRecord::unit() const {
    return label->unit;
}

Measurement MeasurementRecord::measurement() const {
    Measurement measured;
    measured.name = name();
    measured.value = value;
    measured.unit = unit();
    if (hasLow) {
        measured.low = low;
    }
    if (hasHigh) {
        measured.high = high;
    }
    return measured;
}

ResultEvent MeasurementRecord::event(const TestRecord& test) const {
    auto measured = std::make_shared<const Measurement>(measurement());
    TestMessage described(describeMeasurement(*measured));
    ResultEvent made = events::measurement(std::move(measured), passed, std::move(described));
    made.testName = test.name;
    made.testId = test.id;
    made.time = time;
    made.repetition = repetition;
    return made;
}

std::shared_ptr<const MeasurementRecord::Label> MeasurementLabels::intern(const std::string& name,
                                                                          const std::string& unit) {
    auto key = std::make_pair(name, unit);
    auto found = labels_.find(key);
    if (found == labels_.end()) {
        auto label =
            std::make_shared<const MeasurementRecord::Label>(MeasurementRecord::Label{name, unit});
        found = labels_.emplace(std::move(key), std::move(label)).first;
    }
    return found->second;
}

const std::vector<ResultEvent>& TestRecord::eventsInOrder(std::vector<ResultEvent>& scratch) const {
    if (measurements.empty()) {
        return events;
    }
    scratch.clear();
    scratch.reserve(events.size() + measurements.size());
    std::size_t next = 0;
    for (const MeasurementRecord& measured : measurements) {
        while (next < events.size() && next < measured.position) {
            scratch.push_back(events[next++]);
        }
        scratch.push_back(measured.event(*this));
    }
    while (next < events.size()) {
        scratch.push_back(events[next++]);
    }
    return scratch;
}

MeasurementList::MeasurementList(const MeasurementList& other)
    : items_(other.items_ == nullptr
                 ? nullptr
                 : std::make_unique<std::vector<MeasurementRecord>>(*other.items_)) {}

MeasurementList& MeasurementList::operator=(const MeasurementList& other) {
    if (this != &other) {
        MeasurementList copy(other);
        items_ = std::move(copy.items_);
    }
    return *this;
}

void MeasurementList::push_back(MeasurementRecord record) {
    if (items_ == nullptr) {
        items_ = std::make_unique<std::vector<MeasurementRecord>>();
    }
    items_->push_back(std::move(record));
}

std::vector<ResultEvent> TestRecord::measurementEvents(const MeasurementList& measured) const {
    std::vector<ResultEvent> made;
    made.reserve(measured.size());
    for (const MeasurementRecord& one : measured) {
        made.push_back(one.event(*this));
    }
    return made;
}

const ResultEvent* TestRecord::reason() const {
    if (status == TestStatus::Passed) {
        return nullptr;
    }
    for (const ResultEvent& event : events) {
        if (stateOf(event.kind) == status) {
            return &event;
        }
    }
    return nullptr;
}

bool SuiteRecord::succeeded() const {
    if (fixtureFailed) {
        return false;
    }
    return std::none_of(tests.begin(), tests.end(),
                        [](const TestRecord& test) { return isFailure(test.status); });
}

TestResultCollector::TestResultCollector()
    : origin_(std::chrono::steady_clock::now()), wallOrigin_(std::chrono::system_clock::now()) {}

TestResultCollector::~TestResultCollector() = default;

void TestResultCollector::reset() {
    origin_ = std::chrono::steady_clock::now();
    wallOrigin_ = std::chrono::system_clock::now();
    start_ = 0;
    end_ = -1;
    events_.clear();
    suites_.clear();
    worlds_.clear();
    labels_.clear();
    openSuites_.clear();
    openTests_.clear();
    lastEnded_ = {0, nullptr, none, none};
    retrying_ = {0, nullptr, none, none};
    looseSuite_ = none;
    std::fill(std::begin(counts_), std::end(counts_), 0);
    outputKept_ = 0;
    suitesRun_ = 0;
    suitesFailed_ = 0;
    fixturesFailed_ = 0;
}

double TestResultCollector::now() const {
    if (delivering_ != nullptr && delivering_->happened > 0) {
        return delivering_->happened -
               std::chrono::duration<double>(origin_.time_since_epoch()).count();
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - origin_).count();
}

double TestResultCollector::duration() const {
    return (end_ >= 0 ? end_ : now()) - start_;
}

std::size_t TestResultCollector::testCount() const {
    std::size_t total = 0;
    for (std::size_t count : counts_) {
        total += count;
    }
    return total;
}

std::size_t TestResultCollector::countOf(TestStatus status) const {
    return counts_[static_cast<std::size_t>(status)];
}

std::size_t TestResultCollector::passedCount() const {
    return countOf(TestStatus::Passed);
}

std::size_t TestResultCollector::skippedCount() const {
    return countOf(TestStatus::Skipped);
}

std::size_t TestResultCollector::failedCount() const {
    return testCount() - passedCount() - skippedCount() - countOf(TestStatus::Flaky);
}

std::size_t TestResultCollector::suiteCount() const {
    return suitesRun_;
}

std::size_t TestResultCollector::passedSuiteCount() const {
    return suitesRun_ - suitesFailed_;
}

std::size_t TestResultCollector::failedSuiteCount() const {
    return suitesFailed_;
}

std::size_t TestResultCollector::failedFixtureCount() const {
    return fixturesFailed_;
}

SuiteRecord& TestResultCollector::currentSuite() {
    if (!openSuites_.empty()) {
        return suites_[openSuites_.back().index];
    }
    if (looseSuite_ == none) {
        if (!keepEvents_ && openTests_.empty()) {
            suites_.clear();
        }
        suites_.emplace_back();
        suites_.back().start = now();
        looseSuite_ = suites_.size() - 1;
    }
    return suites_[looseSuite_];
}

TestResultCollector::OpenTest* TestResultCollector::findOpen(const Test* test) {
    const std::uint64_t id = test != nullptr ? test->getId() : 0;
    for (auto it = openTests_.rbegin(); it != openTests_.rend(); ++it) {
        if (it->id == id) {
            return &*it;
        }
    }
    return nullptr;
}

void TestResultCollector::onEvent(const RunEvent& event) {
    const RunEvent* outer = delivering_;  // a handler may publish again (a subclass's own)
    delivering_ = &event;
    try {
        if (isWorldPhase(event.data.kind)) {
            recordWorld(event.data);
        }
        TestListener::onEvent(event);
    } catch (...) {
        delivering_ = outer;
        throw;
    }
    delivering_ = outer;
}

void TestResultCollector::recordWorld(const ResultEvent& event) {
    const double at = now();
    const std::string phase = event.message.getMessage();
    WorldRecord* world = nullptr;
    for (auto it = worlds_.rbegin(); it != worlds_.rend() && world == nullptr; ++it) {
        if (it->name == event.testName && it->stop < 0) {
            world = &*it;
        }
    }
    if (world == nullptr || phase == "start") {
        worlds_.emplace_back();
        world = &worlds_.back();
        world->name = event.testName;
        world->start = at;
    }
    if (phase == "start") {
        world->users = event.message.getDetail();
    } else if (phase == "ready") {
        world->ready = at;
    } else if (phase == "stop") {
        world->stop = at;
        if (!event.message.getDetail().empty()) {
            world->reason += (world->reason.empty() ? "" : "; ") + event.message.getDetail();
        }
    } else {
        world->failed = at;
        world->reason = event.message.getDetail();
        if (phase == "failed") {
            world->stop = at;
        }
    }
}

const RunEvent* TestResultCollector::timeAs(const RunEvent* event) {
    const RunEvent* before = delivering_;
    delivering_ = event;
    return before;
}

void TestResultCollector::record(const Test* test, ResultEvent&& made,
                                 const Measurement* measurement) {
    const ResultEvent::Kind kind = made.kind;
    // A test's own event goes to its record (and its repetition); anything else open (a
    // fixture's report from a watcher thread, a collapse) belongs to the suite.
    const OpenTest* open = findOpen(test);
    TestRecord* owner = open != nullptr ? &suites_[open->suite].tests[open->index] : nullptr;
    const bool logged = keepEvents_ && keepLog_;
    if (owner != nullptr && isCheck(kind) && !keepChecks_ && !logged) {
        return;  // most events of a passing test are checks: nothing of them is copied
    }
    if (owner != nullptr && measurement != nullptr) {
        // Measurements leave the test's state as it is (one outside its limits is followed
        // by the failure that says so).
        MeasurementRecord measured;
        measured.label = labels_.intern(measurement->name, measurement->unit);
        measured.value = measurement->value;
        measured.hasLow = measurement->low.has_value();
        measured.low = measurement->low.value_or(0);
        measured.hasHigh = measurement->high.has_value();
        measured.high = measurement->high.value_or(0);
        measured.time = now();
        measured.repetition = open->repetition;
        measured.position = static_cast<std::uint32_t>(owner->events.size());
        measured.passed = made.passed;
        owner->measurements.push_back(std::move(measured));
        if (!logged) {
            return;
        }
        ResultEvent event = stamped(std::move(made), test, now());
        event.measurement = std::make_shared<const Measurement>(*measurement);
        event.repetition = open->repetition;
        events_.push_back(std::move(event));
        return;
    }
    ResultEvent event = stamped(std::move(made), test, now());
    if (measurement != nullptr) {
        event.measurement = std::make_shared<const Measurement>(*measurement);
    }
    if (owner != nullptr) {
        event.repetition = open->repetition;
        if (isOutput(kind)) {
            owner->output += event.message.getMessage();
        } else if (!isCheck(kind) || keepChecks_) {
            owner->status = std::max(owner->status, stateOf(kind));
            if (event.repetition != 0 && !owner->repetitions.empty()) {
                TestStatus& state = owner->repetitions.back().status;
                state = std::max(state, stateOf(kind));
            }
            owner->events.push_back(logged ? event : std::move(event));
        }
    } else if (!openSuites_.empty()) {
        SuiteRecord& suite = suites_[openSuites_.back().index];
        if (isOutput(kind)) {
            suite.output += event.message.getMessage();
        } else {
            if (isFailure(stateOf(kind))) {
                suite.fixtureFailed = true;
            }
            suite.events.push_back(logged ? event : std::move(event));
        }
    }
    if (logged) {
        events_.push_back(std::move(event));
    }
}

void TestResultCollector::addReport(const Test* test, TestMessage msg) {
    record(test, events::report(std::move(msg)));
}

void TestResultCollector::addError(const Test* test, TestMessage msg) {
    record(test, events::error(std::move(msg)));
}

void TestResultCollector::addFailure(const Test* test, TestMessage msg) {
    record(test, events::failure(std::move(msg)));
}

void TestResultCollector::addCheck(const Test* test, TestMessage msg, bool passed) {
    record(test, events::check(std::move(msg), passed));
}

void TestResultCollector::addSkipped(const Test* test, TestMessage reason) {
    record(test, events::skipped(std::move(reason)));
}

void TestResultCollector::addCrash(const Test* test, TestMessage msg) {
    record(test, events::crash(std::move(msg)));
}

void TestResultCollector::addTimeout(const Test* test, TestMessage msg) {
    record(test, events::timeout(std::move(msg)));
}

void TestResultCollector::addInterrupted(const Test* test, TestMessage msg) {
    record(test, events::interrupted(std::move(msg)));
}

void TestResultCollector::addOutput(const Test* test, const std::string& text) {
    record(test, events::output(text));
}

void TestResultCollector::addEvent(const Test* test, const ResultEvent& event) {
    if (isWorldPhase(event.kind)) {
        return;  // kept by onEvent, in worlds()
    }
    // Kept as any other: its kind, message and outcome, and what it carries.
    ResultEvent kept;
    kept.kind = event.kind;
    kept.message = event.message;
    kept.passed = event.passed;
    kept.attachment = event.attachment;
    record(test, std::move(kept), event.measurement.get());
}

void TestResultCollector::addMeasurement(const Test* test, const Measurement& measurement,
                                         bool passed) {
    // The message is made only if an event is kept (a suite's, or the event log's): a test's
    // record keeps a MeasurementRecord, which describes itself when a report asks.
    const OpenTest* open = findOpen(test);
    const bool eventKept = open == nullptr || (keepEvents_ && keepLog_);
    record(test,
           events::measurement(
               nullptr, passed,
               eventKept ? TestMessage(describeMeasurement(measurement)) : TestMessage()),
           &measurement);
}

void TestResultCollector::addAttachment(const Test* test, const Attachment& attachment) {
    // Few (a test's files, a fixture's logs): each record keeps its own copy.
    record(test, events::attachment(std::make_shared<const Attachment>(attachment),
                                    TestMessage(describeAttachment(attachment))));
}

void TestResultCollector::renameTest(const Test* test, const std::string& name) {
    const std::uint64_t id = test != nullptr ? test->getId() : 0;
    for (auto it = openTests_.rbegin(); it != openTests_.rend(); ++it) {
        if (it->id == id) {
            suites_[it->suite].tests[it->index].name = name;
            return;
        }
    }
}

void TestResultCollector::startRepetition(const Test* test, unsigned int index,
                                          unsigned int count) {
    OpenTest* open = findOpen(test);
    if (open != nullptr) {
        const double time = now();
        TestRecord& owner = suites_[open->suite].tests[open->index];
        if (!owner.repetitions.empty()) {
            owner.repetitions.back().duration = time - owner.repetitions.back().start;
        }
        TestRepetition repetition;
        repetition.index = index;
        repetition.count = count;
        repetition.start = time;
        owner.repetitions.push_back(repetition);
        open->repetition = index;
    }
    record(test, events::report(repetitionMessage(index, count)));
}

void TestResultCollector::retryTest(const Test* test, TestMessage msg) {
    if (test == nullptr || lastEnded_.id != test->getId() || lastEnded_.suite >= suites_.size() ||
        lastEnded_.index >= suites_[lastEnded_.suite].tests.size()) {
        return;
    }
    if (keepEvents_ && keepLog_) {
        events_.push_back(stamped(events::report(msg), test, now()));
    }
    // The failed attempt stops counting: the test's state is its last attempt's.
    TestRecord& record = suites_[lastEnded_.suite].tests[lastEnded_.index];
    --counts_[static_cast<std::size_t>(record.status)];
    if (isFailure(record.status)) {
        for (OpenSuite& suite : openSuites_) {
            if (suite.index == lastEnded_.suite && suite.failed > 0) {
                --suite.failed;
            }
        }
    }
    TestAttempt attempt;
    attempt.status = record.status;
    if (const ResultEvent* reason = record.reason()) {
        attempt.message = reason->message;
    }
    attempt.output = std::move(record.output);
    attempt.duration = record.duration;
    attempt.measurements = std::move(record.measurements);
    record.attempts.push_back(std::move(attempt));
    record.status = TestStatus::Passed;
    record.events.clear();
    record.measurements.clear();
    record.output.clear();
    record.repetitions.clear();
    retrying_ = lastEnded_;
    lastEnded_ = {0, nullptr, none, none};
}

void TestResultCollector::startTest(const Test* test) {
    const double time = now();
    if (keepEvents_ && keepLog_) {
        events_.push_back(stamped(events::startTest(), test, time));
    }
    if (test != nullptr && retrying_.id != 0 && retrying_.id == test->getId()) {
        OpenTest reopened = retrying_;
        reopened.test = test;
        reopened.repetition = 0;
        openTests_.push_back(reopened);  // the same record, one attempt more
        retrying_ = {0, nullptr, none, none};
        return;
    }
    retrying_ = {0, nullptr, none, none};
    SuiteRecord& suite = currentSuite();
    if (!keepEvents_ && openTests_.empty()) {
        suite.tests.clear();  // only the test being run is kept
    }
    suite.tests.emplace_back();
    TestRecord& record = suite.tests.back();
    if (test != nullptr) {
        record.id = test->getId();
        record.name = test->getName();
        record.key = test->getKey();
        record.description = test->getDescription();
    }
    record.start = time;
    openTests_.push_back({record.id, test, static_cast<std::size_t>(&suite - suites_.data()),
                          suite.tests.size() - 1});
}

void TestResultCollector::endTest(const Test* test) {
    const double time = now();
    if (keepEvents_ && keepLog_) {
        events_.push_back(stamped(events::endTest(), test, time));
    }
    const std::uint64_t id = test != nullptr ? test->getId() : 0;
    for (std::size_t i = openTests_.size(); i > 0; --i) {
        const OpenTest open = openTests_[i - 1];
        if (open.id != id) {
            continue;
        }
        TestRecord& record = suites_[open.suite].tests[open.index];
        record.duration = time - record.start;
        if (!record.repetitions.empty()) {
            record.repetitions.back().duration = time - record.repetitions.back().start;
        }
        if (!record.attempts.empty() && record.status == TestStatus::Passed) {
            record.status = TestStatus::Flaky;
        }
        keepWithinBudget(record.output);
        // Skipped because its suite's fixture had failed before it: RTF 2.x did not count it.
        const bool notRun =
            record.status == TestStatus::Skipped && suites_[open.suite].fixtureFailed;
        if (!notRun || countNotRun_) {
            ++counts_[static_cast<std::size_t>(record.status)];
        }
        if (isFailure(record.status)) {
            for (OpenSuite& suite : openSuites_) {
                if (suite.index == open.suite) {
                    ++suite.failed;
                }
            }
        }
        if (open.suite == looseSuite_) {
            suites_[open.suite].duration = time - suites_[open.suite].start;
        }
        lastEnded_ = open;
        openTests_.erase(openTests_.begin() + static_cast<std::ptrdiff_t>(i - 1), openTests_.end());
        break;
    }
}

void TestResultCollector::keepWithinBudget(std::string& output) {
    constexpr std::size_t tail = 4096;
    if (!keepEvents_) {
        return;  // the records are dropped test by test anyway
    }
    if (outputBudget_ != 0 && outputKept_ + output.size() > outputBudget_ && output.size() > tail) {
        output = "[... " + std::to_string(output.size() - tail) +
                 " bytes of output left out: the run's reports keep " +
                 std::to_string(outputBudget_ / 1024) + " KiB of output in all]\n" +
                 output.substr(output.size() - tail);
    }
    outputKept_ += output.size();
}

void TestResultCollector::startTestSuite(const TestSuite* suite) {
    const double time = now();
    if (keepEvents_ && keepLog_) {
        events_.push_back(stamped(events::startSuite(), suite, time));
    }
    if (!keepEvents_ && openSuites_.empty() && openTests_.empty()) {
        suites_.clear();
    }
    looseSuite_ = none;
    suites_.emplace_back();
    SuiteRecord& record = suites_.back();
    if (suite != nullptr) {
        record.id = suite->getId();
        record.name = suite->getName();
        record.description = suite->getDescription();
        if (keepEvents_) {
            // Exactly once: a growing vector of records holds two copies while it moves.
            record.tests.reserve(suite->size());
        }
    }
    record.start = time;
    openSuites_.push_back({suites_.size() - 1, 0});
}

void TestResultCollector::endTestSuite(const TestSuite* suite) {
    const double time = now();
    if (keepEvents_ && keepLog_) {
        events_.push_back(stamped(events::endSuite(), suite, time));
    }
    if (openSuites_.empty()) {
        return;
    }
    SuiteRecord& record = suites_[openSuites_.back().index];
    record.duration = time - record.start;
    ++suitesRun_;
    if (openSuites_.back().failed > 0 || !record.succeeded()) {
        ++suitesFailed_;
    }
    if (record.fixtureFailed) {
        ++fixturesFailed_;
    }
    openSuites_.pop_back();
}

void TestResultCollector::interruptOpen(const TestMessage& why) {
    std::set<std::size_t> cut;  // the suites whose test is interrupted here
    while (!openTests_.empty()) {
        const std::size_t open = openTests_.size();
        const Test* test = openTests_.back().test;
        cut.insert(openTests_.back().suite);
        addInterrupted(test, why);
        endTest(test);
        if (openTests_.size() == open) {
            openTests_.pop_back();  // never left open for ever
        }
    }
    while (!openSuites_.empty()) {
        // A suite whose test was interrupted fails by it. Another one open was in its fixtures'
        // tearDown (or, before any test, their set-up), which did not finish: the suite is
        // interrupted with `why` and says so, which fails it as a failed fixture does (a run
        // cut short is never reported passed).
        if (cut.count(openSuites_.back().index) != 0) {
            endTestSuite(nullptr);
            continue;
        }
        const bool anyTest = !suites_[openSuites_.back().index].tests.empty();
        const std::string phase = anyTest ? "tearDown" : "set-up";
        addInterrupted(nullptr, TestMessage(why.getMessage() + ": the " + phase +
                                                " of the suite's fixtures did not finish",
                                            why.getDetail(), why.getSourceFileName(),
                                            why.getSourceLineNumber()));
        endTestSuite(nullptr);
    }
    if (end_ < 0) {
        endTestRunner();
    }
}

void TestResultCollector::startTestRunner() {
    start_ = now();
    end_ = -1;
    if (keepEvents_ && keepLog_) {
        events_.push_back(stamped(events::startRunner(), nullptr, start_));
    }
}

void TestResultCollector::endTestRunner() {
    end_ = now();
    if (keepEvents_ && keepLog_) {
        events_.push_back(stamped(events::endRunner(), nullptr, end_));
    }
}

}  // namespace robottestingframework
