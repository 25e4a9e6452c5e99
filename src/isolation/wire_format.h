// The bytes between the runner and its workers. A stream of records, each framed by its
// length, so a reader can tell a whole record from a truncated one and refuse garbage:
//
//   record  = u32 body-length, body                       (little-endian)
//   body    = u8 kind, u8 event, u8 flag, i64 number, str name, str message, str detail,
//             str file, u32 line, diagnostics, u32 repetition, u32 repetitions, payload
//   diagnostics = u32 count, count × (str key, str value)   (the message's diagnostics)
//   payload = u8 0                                          (nothing)
//           | u8 1, str name, f64 value, str unit, limit low, limit high   (a measurement)
//           | u8 2, str path, str absolute-path, str description, str original-name, i64 size
//   limit   = u8 0 | u8 1, f64                             (f64: the IEEE bits as an i64)
//   str     = u32 length, bytes
//
// Requests to the fork server are single packets of their own layout (encodeRequest).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestMessage.h>

namespace robottestingframework {
namespace isolation {

enum class WireKind : std::uint8_t {
    Event = 1,           // worker → runner: a ResultEvent of any kind (eventRecord, eventOf)
    CriticalError,       // worker → runner: the test raised a critical error (`message`)
    FixtureCollapsed,    // fixture worker → runner: the fixture's world is gone (`message`)
    Reply,               // fixture worker → runner: a call returned `flag` (`message`: why not)
    Finished,            // worker → runner: the test ended normally; the worker exits now
    Started,             // fork server → runner: the worker's pid is `number`
    Exited,              // fork server → runner: the worker ended; `number` is its wait status
    Call,                // runner → fixture worker: `name` is setup/check/tearDown; `message`
                         // holds setup's argv joined by '\0'
    Described,           // worker → runner: the loaded test's `name` and description (`message`)
    FixtureCheckFailed,  // fixture worker → runner: a record of the fixture's own failed at its
                         // tear-down (`name`, `message`, its log as `attachment`)
};

struct WireRecord {
    WireKind kind = WireKind::Event;
    ResultEvent::Kind event{};  // an Event record's kind (the others carry none)
    std::string name;
    TestMessage message;
    bool flag = true;
    std::int64_t number = 0;
    std::uint32_t repetition = 0;   // an event's ResultEvent::repetition
    std::uint32_t repetitions = 0;  // an event's ResultEvent::repetitions
    std::shared_ptr<const Measurement> measurement =
        nullptr;                                             // an event's ResultEvent::measurement
    std::shared_ptr<const Attachment> attachment = nullptr;  // an event's ResultEvent::attachment
};

// The Event record that carries `event` (about the test named `name`), field by field: what
// travels is the event itself, whatever its kind.
WireRecord eventRecord(const ResultEvent& event, const std::string& name);
// The event an Event record carries (its testName is the record's name).
ResultEvent eventOf(const WireRecord& record);

// A record longer than this is garbage, not a record.
constexpr std::size_t kMaxRecordSize = 16 * 1024 * 1024;

// Appends the framed record to `out`.
void encode(const WireRecord& record, std::string& out);
std::string encode(const WireRecord& record);

// Reassembles records from the bytes of a stream, however they were split.
class WireDecoder {
public:
    enum class Status { Record, NeedMore, Corrupt };

    void feed(const char* data, std::size_t size) { buffer_.append(data, size); }
    void feed(const std::string& data) { buffer_.append(data); }
    // Record: `record` filled. NeedMore: wait for more bytes. Corrupt: the stream is unusable
    // (every later call says so too).
    Status next(WireRecord& record);
    // Bytes received that are not (yet) a whole record.
    std::size_t pending() const { return buffer_.size() - offset_; }

private:
    std::string buffer_;
    std::size_t offset_ = 0;
    bool corrupt_ = false;
};

// What the runner asks the fork server to start.
struct WorkRequest {
    enum class Role : std::uint8_t { Test = 1, Fixture };
    Role role = Role::Test;
    std::string type;  // "dll", "python", ... as languages::loadTest takes it
    std::string path;  // the resolved file
    std::string name;  // the name to give it (empty: the plug-in's own)
    std::string param;
    std::string environment;  // the suite's environment string (TestCase::setEnvironment)
    std::uint32_t repetition = 1;
    std::vector<std::string> variables;  // "NAME=VALUE" set in the worker's environment
};

std::string encodeRequest(const WorkRequest& request);
// False when `data` is not exactly one well-formed request.
bool decodeRequest(const std::string& data, WorkRequest& request);

// The fork server's spares handed to the runner (fork_server_loop.h): the server announces
// one (its pid; the spare's end of the link goes with the packet), the runner claims the one it
// sent a request to (the status pipe goes with the packet). Never a well-formed request.
enum class SpareNote : char { Announced = 'S', Claimed = 'C' };
std::string encodeSpareNote(SpareNote note, std::int64_t pid);
// False when `data` is not exactly one spare note.
bool decodeSpareNote(const std::string& data, SpareNote& note, std::int64_t& pid);

}  // namespace isolation
}  // namespace robottestingframework
