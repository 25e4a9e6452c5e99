// Fuzz target: what a worker writes on its channel, as the runner reads it (cmake/Fuzz.cmake,
// ./run.sh fuzz): bytes cut into reads, reassembled by WireDecoder, each record given to the
// EventRelay of a stand-in test with a collector listening, the way IsolatedExecutor does. A
// worker may write garbage or stop half-way through a record. The first byte chooses how the
// bytes are cut; with its top bit set the rest is a fork server request instead.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>

#include "isolation/event_relay.h"
#include "isolation/wire_format.h"

using namespace robottestingframework;
using namespace robottestingframework::isolation;

namespace {

class StandIn : public Test {
public:
    StandIn() : Test("worker test") {}
    void run(TestResult&) override {}
    bool succeeded() const override { return true; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    if (data[0] & 0x80) {
        WorkRequest request;
        if (decodeRequest(bytes, request) && encodeRequest(request) != bytes) {
            __builtin_trap();  // a request read is the one written
        }
        SpareNote note;
        std::int64_t pid;
        if (decodeSpareNote(bytes, note, pid) &&
            (encodeSpareNote(note, pid) != bytes || decodeRequest(bytes, request))) {
            __builtin_trap();  // a note read is the one written, and never a request
        }
        return 0;
    }
    const std::size_t piece = data[0] + 1;

    StandIn self;
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    EventRelay relay(self, result);
    WireDecoder decoder;
    WireRecord record;
    WireDecoder::Status status = WireDecoder::Status::NeedMore;
    for (std::size_t at = 0; at < bytes.size() && status != WireDecoder::Status::Corrupt;
         at += piece) {
        decoder.feed(bytes.data() + at, std::min(piece, bytes.size() - at));
        while ((status = decoder.next(record)) == WireDecoder::Status::Record) {
            // What is read back encodes to the same bytes as a fresh record of it.
            WireRecord again;
            WireDecoder check;
            check.feed(encode(record));
            if (check.next(again) != WireDecoder::Status::Record ||
                encode(again) != encode(record)) {
                __builtin_trap();
            }
            relay.relay(record);
            record = WireRecord();
        }
    }
    relay.end(decoder.pending() > 0 ? "truncated record" : "");
    return 0;
}
