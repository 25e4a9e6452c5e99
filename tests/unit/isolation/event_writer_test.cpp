// The worker's event writer: every event of a test, whatever its kind, becomes one wire
// record carrying the event's fields; a test's end waits to share a write with the next record.
#include <gtest/gtest.h>

#include <unistd.h>

#include <string>
#include <vector>

#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>

#include "isolation/event_relay.h"
#include "isolation/event_writer.h"
#include "platform/file_descriptor.h"

using namespace robottestingframework;
using namespace robottestingframework::isolation;

namespace {

using Kind = ResultEvent::Kind;

class Named : public TestCase {
public:
    explicit Named(const std::string& name) : TestCase(name) {}
    void run() override {}
};

// A pipe the writer writes to; records() reads back what arrived so far.
class Channel {
public:
    Channel() {
        int fds[2];
        EXPECT_EQ(::pipe(fds), 0);
        read_ = fds[0];
        write_ = fds[1];
    }
    ~Channel() {
        ::close(read_);
        ::close(write_);
    }
    int fd() const { return write_; }
    std::vector<WireRecord> records() {
        platform::setNonBlocking(read_);
        std::string bytes;
        while (platform::readSome(read_, bytes) > 0) {
        }
        decoder_.feed(bytes);
        std::vector<WireRecord> out;
        WireRecord record;
        while (decoder_.next(record) == WireDecoder::Status::Record) {
            out.push_back(record);
        }
        return out;
    }

private:
    int read_ = -1;
    int write_ = -1;
    WireDecoder decoder_;
};

}  // namespace

TEST(EventWriter, EveryKindIsOneRecordCarryingTheEvent) {
    Channel channel;
    EventWriter writer(channel.fd());
    Named test("arm");
    TestResult result;
    result.addListener(&writer);
    std::vector<RunEvent> sent;
    for (unsigned int k = 0; k <= static_cast<unsigned int>(ResultEvent::lastKind); ++k) {
        RunEvent event;
        event.data.kind = static_cast<Kind>(k);
        event.data.message = TestMessage("message " + std::to_string(k), "detail", "arm.cpp", k);
        event.data.passed = k % 2 == 1;
        event.data.repetition = k + 1;
        event.data.repetitions = k + 2;
        event.test = &test;
        result.publish(event);
        sent.push_back(event);
    }
    writer.send(WireRecord{WireKind::Finished, {}, {}, {}, true, 0});  // lets a held one out
    const std::vector<WireRecord> records = channel.records();
    ASSERT_EQ(records.size(), sent.size() + 1);
    for (std::size_t i = 0; i < sent.size(); ++i) {
        const ResultEvent got = eventOf(records[i]);
        EXPECT_EQ(records[i].kind, WireKind::Event);
        EXPECT_EQ(got.kind, sent[i].data.kind) << toString(sent[i].data.kind);
        EXPECT_EQ(got.testName, "arm");
        EXPECT_EQ(got.message.toString(), sent[i].data.message.toString());
        EXPECT_EQ(got.message.getSourceLineNumber(), sent[i].data.message.getSourceLineNumber());
        EXPECT_EQ(got.passed, sent[i].data.passed);
        EXPECT_EQ(got.repetition, sent[i].data.repetition);
        EXPECT_EQ(got.repetitions, sent[i].data.repetitions);
    }
    EXPECT_EQ(records.back().kind, WireKind::Finished);
}

TEST(EventWriter, ATestsEndWaitsForTheNextRecord) {
    Channel channel;
    EventWriter writer(channel.fd());
    Named test("arm");
    TestResult result;
    result.addListener(&writer);
    result.startTest(&test);
    result.endTest(&test);
    const std::vector<WireRecord> first = channel.records();
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].event, Kind::StartTest);
    writer.send(WireRecord{WireKind::Finished, {}, {}, {}, true, 0});
    const std::vector<WireRecord> then = channel.records();
    ASSERT_EQ(then.size(), 2u);
    EXPECT_EQ(then[0].event, Kind::EndTest);
    EXPECT_EQ(then[1].kind, WireKind::Finished);
}

TEST(EventWriter, ARepetitionReachesTheRunnersListenersWithIndexAndCount) {
    Channel channel;
    EventWriter writer(channel.fd());
    Named test("arm");
    TestResult worker;
    worker.addListener(&writer);
    worker.startTest(&test);
    worker.startRepetition(&test, 2, 3);
    worker.addFailure(&test, TestMessage("in the second"));

    Named standIn("arm");
    TestResult run;
    TestResultCollector collector;
    run.addListener(&collector);
    EventRelay relay(standIn, run);
    for (const WireRecord& record : channel.records()) {
        relay.relay(record);
    }
    relay.end("");
    EXPECT_EQ(relay.repetition(), "repetition 2/3");
    const TestRecord& got = collector.suites().at(0).tests.at(0);
    ASSERT_EQ(got.repetitions.size(), 1u);
    EXPECT_EQ(got.repetitions[0].index, 2u);
    EXPECT_EQ(got.repetitions[0].count, 3u);
    EXPECT_EQ(got.repetitions[0].status, TestStatus::Failed);
}

TEST(EventWriter, AKindWithOnlyItsTableRowsReachesTheRunnersListeners) {
    Channel channel;
    EventWriter writer(channel.fd());
    Named test("arm");
    TestResult worker;
    worker.addListener(&writer);
    worker.startTest(&test);
    RunEvent probe;
    probe.data.kind = Kind::Probe;
    probe.data.message = TestMessage("sent as data");
    probe.test = &test;
    worker.publish(probe);

    Named standIn("arm");
    TestResult run;
    TestResultCollector collector;
    run.addListener(&collector);
    EventRelay relay(standIn, run);
    for (const WireRecord& record : channel.records()) {
        relay.relay(record);
    }
    relay.end("");
    const TestRecord& got = collector.suites().at(0).tests.at(0);
    EXPECT_EQ(got.status, stateOf(Kind::Probe));
    ASSERT_NE(got.reason(), nullptr);
    EXPECT_EQ(got.reason()->kind, Kind::Probe);
    EXPECT_EQ(got.reason()->message.getMessage(), "sent as data");
}
