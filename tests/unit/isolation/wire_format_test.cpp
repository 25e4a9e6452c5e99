// The runner/worker wire format: records survive any split of the stream, and truncated or
// garbage input is never mistaken for a record.
#include <gtest/gtest.h>

#include <string>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>

#include "isolation/event_relay.h"
#include "isolation/wire_format.h"

using robottestingframework::ResultEvent;
using robottestingframework::TestMessage;
using namespace robottestingframework::isolation;

namespace {

WireRecord sample() {
    WireRecord record;
    record.kind = WireKind::Event;
    record.event = ResultEvent::Kind::Check;
    record.name = "arm test";
    record.message =
        TestMessage("joint 3 \xc3\xa9 in range", std::string("a\0b", 3), "arm.cpp", 42);
    // A TAP point's diagnostics travel with it (issue 38, friction 9).
    record.message.setDiagnostics({{"got", "3"}, {"at", "file: t.sh\nline: 3"}});
    record.flag = false;
    record.number = -1234567890123LL;
    record.repetition = 7;
    record.repetitions = 9;
    return record;
}

void expectSame(const WireRecord& a, const WireRecord& b) {
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.event, b.event);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.message.getMessage(), b.message.getMessage());
    EXPECT_EQ(a.message.getDetail(), b.message.getDetail());
    EXPECT_EQ(a.message.getSourceFileName(), b.message.getSourceFileName());
    EXPECT_EQ(a.message.getSourceLineNumber(), b.message.getSourceLineNumber());
    EXPECT_EQ(a.message.getDiagnostics(), b.message.getDiagnostics());
    EXPECT_EQ(a.flag, b.flag);
    EXPECT_EQ(a.number, b.number);
    EXPECT_EQ(a.repetition, b.repetition);
    EXPECT_EQ(a.repetitions, b.repetitions);
}

}  // namespace

TEST(WireFormat, RecordRoundTripsEveryField) {
    WireDecoder decoder;
    decoder.feed(encode(sample()));
    WireRecord out;
    ASSERT_EQ(decoder.next(out), WireDecoder::Status::Record);
    expectSame(out, sample());
    EXPECT_EQ(decoder.next(out), WireDecoder::Status::NeedMore);
    EXPECT_EQ(decoder.pending(), 0u);
}

TEST(WireFormat, RecordsSplitAtEveryByteAreReassembled) {
    std::string stream = encode(sample());
    WireRecord second;
    second.kind = WireKind::Finished;
    encode(second, stream);
    WireDecoder decoder;
    int records = 0;
    for (char byte : stream) {
        decoder.feed(&byte, 1);
        WireRecord out;
        while (decoder.next(out) == WireDecoder::Status::Record) {
            if (records == 0) {
                expectSame(out, sample());
            } else {
                EXPECT_EQ(out.kind, WireKind::Finished);
            }
            ++records;
        }
    }
    EXPECT_EQ(records, 2);
}

TEST(WireFormat, TruncatedRecordIsNeverReturned) {
    std::string bytes = encode(sample());
    for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
        WireDecoder decoder;
        decoder.feed(bytes.data(), cut);
        WireRecord out;
        EXPECT_EQ(decoder.next(out), WireDecoder::Status::NeedMore) << "cut at " << cut;
    }
}

TEST(WireFormat, OversizedLengthIsCorrupt) {
    WireDecoder decoder;
    decoder.feed(std::string("\xff\xff\xff\xff garbage", 12));
    WireRecord out;
    EXPECT_EQ(decoder.next(out), WireDecoder::Status::Corrupt);
    decoder.feed(encode(sample()));
    EXPECT_EQ(decoder.next(out), WireDecoder::Status::Corrupt) << "corrupt stays corrupt";
}

TEST(WireFormat, BodyWithBadKindOrStringLengthIsCorrupt) {
    std::string bytes = encode(sample());
    std::string badKind = bytes;
    badKind[4] = 99;  // the kind byte, just after the length
    WireDecoder first;
    first.feed(badKind);
    WireRecord out;
    EXPECT_EQ(first.next(out), WireDecoder::Status::Corrupt);

    std::string badString = bytes;
    badString[4 + 3 + 8] = static_cast<char>(0x7f);  // the name's length runs past the body
    WireDecoder second;
    second.feed(badString);
    EXPECT_EQ(second.next(out), WireDecoder::Status::Corrupt);
}

TEST(WireFormat, RandomGarbageNeverCrashesTheDecoder) {
    unsigned int seed = 12345;
    for (int round = 0; round < 2000; ++round) {
        std::string junk;
        for (int i = 0; i < 64; ++i) {
            seed = seed * 1103515245u + 12345u;
            junk.push_back(static_cast<char>(seed >> 16));
        }
        junk[0] = static_cast<char>(round % 60);  // small lengths, so bodies get parsed
        junk[1] = junk[2] = junk[3] = 0;
        WireDecoder decoder;
        decoder.feed(junk);
        WireRecord out;
        WireDecoder::Status status;
        int guard = 0;
        while ((status = decoder.next(out)) == WireDecoder::Status::Record && ++guard < 100) {
        }
        EXPECT_NE(status, WireDecoder::Status::Record);
    }
}

TEST(WireFormat, RequestRoundTripsAndRejectsTrailingBytes) {
    WorkRequest request;
    request.role = WorkRequest::Role::Fixture;
    request.type = "dll";
    request.path = "/tmp/libx.so";
    request.name = "x";
    request.param = "--robot icubSim";
    request.environment = "--env 1";
    request.repetition = 7;
    std::string bytes = encodeRequest(request);
    WorkRequest out;
    ASSERT_TRUE(decodeRequest(bytes, out));
    EXPECT_EQ(out.role, WorkRequest::Role::Fixture);
    EXPECT_EQ(out.path, "/tmp/libx.so");
    EXPECT_EQ(out.param, "--robot icubSim");
    EXPECT_EQ(out.environment, "--env 1");
    EXPECT_EQ(out.repetition, 7u);
    EXPECT_FALSE(decodeRequest(bytes + "x", out));
    EXPECT_FALSE(decodeRequest(bytes.substr(0, bytes.size() - 1), out));
    EXPECT_FALSE(decodeRequest("", out));
}

namespace {

class StandIn : public robottestingframework::Test {
public:
    StandIn() : Test("planned name") {}
    void run(robottestingframework::TestResult&) override {}
    bool succeeded() const override { return true; }
};

}  // namespace

TEST(EventRelay, ARenameRecordIsARenameEventAboutTheStandInById) {
    using robottestingframework::TestResult;
    using robottestingframework::TestResultCollector;
    StandIn self;
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    EventRelay relay(self, result);
    WireRecord start;
    start.event = ResultEvent::Kind::StartTest;
    start.name = "planned name";
    relay.relay(start);
    WireRecord failure;
    failure.event = ResultEvent::Kind::Failure;
    failure.name = "planned name";
    failure.message = TestMessage("before the rename");
    relay.relay(failure);
    WireRecord rename;
    rename.event = ResultEvent::Kind::Rename;
    rename.name = "planned name";
    rename.message = TestMessage("new name");
    // Through the bytes, as a worker sends it.
    WireDecoder decoder;
    decoder.feed(encode(rename));
    WireRecord decoded;
    ASSERT_EQ(decoder.next(decoded), WireDecoder::Status::Record);
    relay.relay(decoded);
    relay.end("");
    const auto& test = collector.suites().at(0).tests.at(0);
    EXPECT_EQ(test.id, self.getId());
    EXPECT_EQ(test.name, "new name");
    EXPECT_EQ(test.status, robottestingframework::TestStatus::Failed);
    EXPECT_EQ(test.events.at(0).testId, self.getId());
    EXPECT_EQ(self.getName(), "new name");
}

TEST(EventRelay, ANameDescribedAfterTheStartIsARenameEvent) {
    using robottestingframework::TestResult;
    using robottestingframework::TestResultCollector;
    StandIn self;
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    EventRelay relay(self, result);
    relay.start();  // the runner may start the test before the worker describes it
    WireRecord described;
    described.kind = WireKind::Described;
    described.name = "the plug-in's own name";
    relay.relay(described);
    relay.end("");
    EXPECT_EQ(collector.suites().at(0).tests.at(0).name, "the plug-in's own name");
}

TEST(WireFormat, AMeasurementTravelsWithItsLimitsExactly) {
    robottestingframework::ResultEvent event;
    event.kind = ResultEvent::Kind::Measurement;
    event.passed = false;
    event.measurement = std::make_shared<const robottestingframework::Measurement>(
        robottestingframework::Measurement{"loop rate", 0.1 + 0.2, "Hz", 95.5, std::nullopt});
    WireDecoder decoder;
    decoder.feed(encode(eventRecord(event, "arm")));
    WireRecord record;
    ASSERT_EQ(decoder.next(record), WireDecoder::Status::Record);
    const ResultEvent back = eventOf(record);
    ASSERT_TRUE(back.measurement);
    EXPECT_EQ(back.measurement->name, "loop rate");
    EXPECT_EQ(back.measurement->value, 0.1 + 0.2);  // bit for bit
    EXPECT_EQ(back.measurement->unit, "Hz");
    EXPECT_EQ(back.measurement->low, 95.5);
    EXPECT_FALSE(back.measurement->high);
    EXPECT_FALSE(back.passed);
    EXPECT_FALSE(back.attachment);
}

TEST(WireFormat, AnAttachmentTravelsWhole) {
    robottestingframework::ResultEvent event;
    event.kind = ResultEvent::Kind::Attachment;
    event.attachment =
        std::make_shared<const robottestingframework::Attachment>(robottestingframework::Attachment{
            "rtf-attachments/1-plot.svg", "/r/rtf-attachments/1-plot.svg", "tracking", "plot.svg",
            1234567890123ULL});
    WireDecoder decoder;
    decoder.feed(encode(eventRecord(event, "arm")));
    WireRecord record;
    ASSERT_EQ(decoder.next(record), WireDecoder::Status::Record);
    const ResultEvent back = eventOf(record);
    ASSERT_TRUE(back.attachment);
    EXPECT_EQ(back.attachment->path, "rtf-attachments/1-plot.svg");
    EXPECT_EQ(back.attachment->absolutePath, "/r/rtf-attachments/1-plot.svg");
    EXPECT_EQ(back.attachment->description, "tracking");
    EXPECT_EQ(back.attachment->originalName, "plot.svg");
    EXPECT_EQ(back.attachment->size, 1234567890123ULL);
}

TEST(WireFormat, AnUnknownPayloadIsCorrupt) {
    std::string bytes = encode(sample());
    bytes.back() = 7;  // the payload tag: neither none, a measurement nor an attachment
    WireDecoder decoder;
    decoder.feed(bytes);
    WireRecord record;
    EXPECT_EQ(decoder.next(record), WireDecoder::Status::Corrupt);
}

TEST(WireFormat, AFixtureCheckTravelsWithItsNameMessageAndLog) {
    WireRecord record;
    record.kind = WireKind::FixtureCheckFailed;
    record.name = "world 'lab': stop of 'server'";
    record.message = TestMessage("'server' exited with status 1", "", "/lab/world.xml", 7);
    robottestingframework::Attachment log;
    log.path = "rtf-attachments/2-server.log";
    log.absolutePath = "/lab/rtf-attachments/2-server.log";
    log.description = "log of process server";
    log.originalName = "server.log";
    log.size = 76;
    record.attachment = std::make_shared<const robottestingframework::Attachment>(log);
    WireDecoder decoder;
    decoder.feed(encode(record));
    WireRecord back;
    ASSERT_EQ(decoder.next(back), WireDecoder::Status::Record);
    EXPECT_EQ(back.kind, WireKind::FixtureCheckFailed);
    EXPECT_EQ(back.name, record.name);
    EXPECT_EQ(back.message.getMessage(), "'server' exited with status 1");
    EXPECT_EQ(back.message.getSourceLineNumber(), 7u);
    ASSERT_TRUE(back.attachment);
    EXPECT_EQ(back.attachment->absolutePath, log.absolutePath);
    EXPECT_EQ(back.attachment->size, 76u);
}
