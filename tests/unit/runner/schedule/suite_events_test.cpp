// The per-suite event queue: events are kept as data, in order, whatever their kind, until the
// scheduler's thread takes them and replays them to the run's listeners.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestSuite.h>

#include "runner/schedule/suite_events.h"

using namespace robottestingframework;
using robottestingframework::runner::SuiteEvents;

namespace {

using Kind = ResultEvent::Kind;

class Named : public TestCase {
public:
    explicit Named(const std::string& name) : TestCase(name) {}
    void run() override {}
};

// Keeps every event it is handed, as data.
class Recorder : public TestListener {
public:
    void onEvent(const RunEvent& event) override { events.push_back(event); }
    std::vector<RunEvent> events;
};

// One event of each kind there is, each with fields of its own, so that a field lost or mixed
// up on the way shows.
std::vector<RunEvent> oneOfEachKind(const Test* test, const TestSuite* suite) {
    std::vector<RunEvent> events;
    for (unsigned int k = 0; k <= static_cast<unsigned int>(ResultEvent::lastKind); ++k) {
        RunEvent event;
        event.data.kind = static_cast<Kind>(k);
        event.data.message = TestMessage("message " + std::to_string(k), "detail", "file.cpp", k);
        event.data.passed = k % 2 == 0;
        event.data.repetition = k;
        event.data.repetitions = k + 1;
        event.test = test;
        event.suite = suite;
        events.push_back(event);
    }
    return events;
}

void expectSame(const RunEvent& a, const RunEvent& b) {
    EXPECT_EQ(a.data.kind, b.data.kind);
    EXPECT_EQ(a.data.message.toString(), b.data.message.toString());
    EXPECT_EQ(a.data.message.getSourceLineNumber(), b.data.message.getSourceLineNumber());
    EXPECT_EQ(a.data.passed, b.data.passed);
    EXPECT_EQ(a.data.repetition, b.data.repetition);
    EXPECT_EQ(a.data.repetitions, b.data.repetitions);
    EXPECT_EQ(a.test, b.test);
    EXPECT_EQ(a.suite, b.suite);
}

}  // namespace

TEST(SuiteEvents, KeepsEveryKindInOrderUntilTaken) {
    Named test("t");
    TestSuite suite("s");
    SuiteEvents queue(nullptr);
    TestResult result;
    result.addListener(&queue);
    const std::vector<RunEvent> sent = oneOfEachKind(&test, &suite);
    for (const RunEvent& event : sent) {
        result.publish(event);
    }
    const std::vector<RunEvent> taken = queue.take();
    ASSERT_EQ(taken.size(), sent.size());
    for (std::size_t i = 0; i < sent.size(); ++i) {
        expectSame(taken[i], sent[i]);
    }
    EXPECT_TRUE(queue.take().empty());
}

TEST(SuiteEvents, ReplayHandsEveryKindToTheListenersUnchanged) {
    Named test("t");
    TestSuite suite("s");
    SuiteEvents queue(nullptr);
    for (const RunEvent& event : oneOfEachKind(&test, &suite)) {
        queue.onEvent(event);
    }
    TestResult run;
    Recorder recorder;
    run.addListener(&recorder);
    const std::vector<RunEvent> taken = queue.take();
    for (const RunEvent& event : taken) {
        run.publish(event);
    }
    ASSERT_EQ(recorder.events.size(), taken.size());
    for (std::size_t i = 0; i < taken.size(); ++i) {
        expectSame(recorder.events[i], taken[i]);
    }
}

TEST(SuiteEvents, WakesOncePerBatch) {
    Named test("t");
    int wakes = 0;
    SuiteEvents queue([&wakes] { ++wakes; });
    TestResult result;
    result.addListener(&queue);
    result.startTest(&test);
    result.addReport(&test, TestMessage("one"));
    result.endTest(&test);
    EXPECT_EQ(wakes, 1);
    EXPECT_EQ(queue.take().size(), 3u);
    result.addReport(&test, TestMessage("two"));
    EXPECT_EQ(wakes, 2);
}

// A running test's start and checks wait for its end (or the scheduler's next look, which takes
// them without a wake-up): one wake-up a test.
TEST(SuiteEvents, ARunningTestWakesOnlyAtItsEnd) {
    Named test("t");
    int wakes = 0;
    SuiteEvents queue([&wakes] { ++wakes; });
    TestResult result;
    result.addListener(&queue);
    result.startTest(&test);
    result.addReport(&test, TestMessage("one"));
    EXPECT_EQ(wakes, 0);
    EXPECT_EQ(queue.take().size(), 2u);  // the look every SuiteEvents::kLookMs
    result.addReport(&test, TestMessage("two"));
    EXPECT_EQ(wakes, 0);
    result.endTest(&test);
    EXPECT_EQ(wakes, 1);
    EXPECT_EQ(queue.take().size(), 2u);
    result.startTest(&test);
    EXPECT_EQ(wakes, 1);
}

// Tests that end in quick succession wake the scheduler once per SuiteEvents::kLookMs: the
// ends in between wait for its next look. What happens outside a test wakes it at once.
TEST(SuiteEvents, TestsEndingSoonAfterAWakeUpWaitForTheNextLook) {
    Named test("t");
    int wakes = 0;
    SuiteEvents queue([&wakes] { ++wakes; });
    TestResult result;
    result.addListener(&queue);
    result.startTest(&test);
    result.endTest(&test);
    EXPECT_EQ(wakes, 1);
    EXPECT_EQ(queue.take().size(), 2u);
    result.startTest(&test);
    result.endTest(&test);
    EXPECT_EQ(wakes, 1);  // taken at the next look
    EXPECT_EQ(queue.take().size(), 2u);
    result.addReport(nullptr, TestMessage("the suite's"));
    EXPECT_EQ(wakes, 2);
    EXPECT_EQ(queue.take().size(), 1u);
    std::this_thread::sleep_for(std::chrono::milliseconds(SuiteEvents::kLookMs + 20));
    result.startTest(&test);
    result.endTest(&test);
    EXPECT_EQ(wakes, 3);
}

TEST(SuiteEvents, RepetitionsTravelAsTheirOwnKindWithIndexAndCount) {
    Named test("t");
    SuiteEvents queue(nullptr);
    TestResult result;
    result.addListener(&queue);
    result.startRepetition(&test, 2, 3);
    const std::vector<RunEvent> taken = queue.take();
    ASSERT_EQ(taken.size(), 1u);
    EXPECT_EQ(taken[0].data.kind, Kind::Repetition);
    EXPECT_EQ(taken[0].data.repetition, 2u);
    EXPECT_EQ(taken[0].data.repetitions, 3u);
}

// Under -j N a suite's events wait while the scheduler's thread runs another suite: replayed
// later, each is still timed in the records when it happened (the timeline's lanes, the
// durations), not when it was handed on.
TEST(SuiteEvents, ReplayedEventsAreTimedWhenTheyHappened) {
    using namespace std::chrono_literals;
    Named test("kept");
    SuiteEvents events([] {});
    TestResult lane;
    lane.addListener(&events);
    TestResultCollector collector;
    TestResult run;
    run.addListener(&collector);
    lane.startTest(&test);
    std::this_thread::sleep_for(200ms);
    lane.endTest(&test);
    std::this_thread::sleep_for(300ms);  // the scheduler's thread is busy elsewhere
    const double handedOn = collector.duration();
    for (const SuiteEvents::Event& event : events.take()) {
        run.publish(event);
    }
    const TestRecord& record = collector.suites().at(0).tests.at(0);
    EXPECT_GE(record.duration, 0.19);
    EXPECT_LE(record.start + record.duration, handedOn - 0.25);
}
