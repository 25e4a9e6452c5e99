#include "isolation/wire_format.h"

#include <cstring>
#include <optional>

namespace robottestingframework {
namespace isolation {

namespace {

constexpr std::uint8_t kLastKind = static_cast<std::uint8_t>(WireKind::FixtureCheckFailed);
constexpr std::uint8_t kLastEvent = static_cast<std::uint8_t>(ResultEvent::lastKind);

void putU32(std::string& out, std::uint32_t value) {
    char bytes[4];
    for (int i = 0; i < 4; ++i) {
        bytes[i] = static_cast<char>((value >> (8 * i)) & 0xff);
    }
    out.append(bytes, 4);
}

void putI64(std::string& out, std::int64_t value) {
    auto bits = static_cast<std::uint64_t>(value);
    putU32(out, static_cast<std::uint32_t>(bits & 0xffffffffu));
    putU32(out, static_cast<std::uint32_t>(bits >> 32));
}

void putString(std::string& out, const std::string& text) {
    putU32(out, static_cast<std::uint32_t>(text.size()));
    out.append(text);
}

void putDouble(std::string& out, double value) {
    std::int64_t bits;
    std::memcpy(&bits, &value, sizeof(bits));
    putI64(out, bits);
}

void putLimit(std::string& out, const std::optional<double>& limit) {
    out.push_back(limit ? 1 : 0);
    if (limit) {
        putDouble(out, *limit);
    }
}

enum Payload : std::uint8_t { kNoPayload = 0, kMeasurement = 1, kAttachment = 2 };

void putPayload(std::string& out, const WireRecord& record) {
    if (record.measurement) {
        const Measurement& measurement = *record.measurement;
        out.push_back(static_cast<char>(kMeasurement));
        putString(out, measurement.name);
        putDouble(out, measurement.value);
        putString(out, measurement.unit);
        putLimit(out, measurement.low);
        putLimit(out, measurement.high);
    } else if (record.attachment) {
        const Attachment& attachment = *record.attachment;
        out.push_back(static_cast<char>(kAttachment));
        putString(out, attachment.path);
        putString(out, attachment.absolutePath);
        putString(out, attachment.description);
        putString(out, attachment.originalName);
        putI64(out, static_cast<std::int64_t>(attachment.size));
    } else {
        out.push_back(static_cast<char>(kNoPayload));
    }
}

// Reads fields from a body, refusing to run past its end.
class Reader {
public:
    Reader(const char* data, std::size_t size) : data_(data), size_(size) {}

    bool u8(std::uint8_t& value) {
        if (size_ - at_ < 1) {
            return false;
        }
        value = static_cast<std::uint8_t>(data_[at_++]);
        return true;
    }
    bool u32(std::uint32_t& value) {
        if (size_ - at_ < 4) {
            return false;
        }
        value = 0;
        for (int i = 0; i < 4; ++i) {
            value |= static_cast<std::uint32_t>(static_cast<unsigned char>(data_[at_ + i]))
                     << (8 * i);
        }
        at_ += 4;
        return true;
    }
    bool i64(std::int64_t& value) {
        std::uint32_t low, high;
        if (!u32(low) || !u32(high)) {
            return false;
        }
        value = static_cast<std::int64_t>((static_cast<std::uint64_t>(high) << 32) | low);
        return true;
    }
    bool string(std::string& text) {
        std::uint32_t length;
        if (!u32(length) || size_ - at_ < length) {
            return false;
        }
        text.assign(data_ + at_, length);
        at_ += length;
        return true;
    }
    bool f64(double& value) {
        std::int64_t bits;
        if (!i64(bits)) {
            return false;
        }
        std::memcpy(&value, &bits, sizeof(value));
        return true;
    }
    bool limit(std::optional<double>& value) {
        std::uint8_t present;
        if (!u8(present) || present > 1) {
            return false;
        }
        if (present == 0) {
            value.reset();
            return true;
        }
        double number;
        if (!f64(number)) {
            return false;
        }
        value = number;
        return true;
    }
    bool done() const { return at_ == size_; }

private:
    const char* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

bool decodePayload(Reader& in, WireRecord& record) {
    std::uint8_t payload;
    if (!in.u8(payload)) {
        return false;
    }
    record.measurement.reset();
    record.attachment.reset();
    if (payload == kMeasurement) {
        auto measurement = std::make_shared<Measurement>();
        if (!in.string(measurement->name) || !in.f64(measurement->value) ||
            !in.string(measurement->unit) || !in.limit(measurement->low) ||
            !in.limit(measurement->high)) {
            return false;
        }
        record.measurement = std::move(measurement);
        return true;
    }
    if (payload == kAttachment) {
        auto attachment = std::make_shared<Attachment>();
        std::int64_t size;
        if (!in.string(attachment->path) || !in.string(attachment->absolutePath) ||
            !in.string(attachment->description) || !in.string(attachment->originalName) ||
            !in.i64(size) || size < 0) {
            return false;
        }
        attachment->size = static_cast<std::uint64_t>(size);
        record.attachment = std::move(attachment);
        return true;
    }
    return payload == kNoPayload;
}

// A message's diagnostics: a count, then each key and value (a count beyond the record's
// bytes fails at the first string that is not there).
bool decodeDiagnostics(Reader& in, TestMessage::Diagnostics& diagnostics) {
    std::uint32_t count = 0;
    if (!in.u32(count)) {
        return false;
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        std::string key, value;
        if (!in.string(key) || !in.string(value)) {
            return false;
        }
        diagnostics.emplace_back(std::move(key), std::move(value));
    }
    return true;
}

bool decodeBody(const char* data, std::size_t size, WireRecord& record) {
    Reader in(data, size);
    std::uint8_t kind, event, flag;
    std::string message, detail, file;
    std::uint32_t line;
    TestMessage::Diagnostics diagnostics;
    if (!in.u8(kind) || !in.u8(event) || !in.u8(flag) || !in.i64(record.number) ||
        !in.string(record.name) || !in.string(message) || !in.string(detail) || !in.string(file) ||
        !in.u32(line) || !decodeDiagnostics(in, diagnostics) || !in.u32(record.repetition) ||
        !in.u32(record.repetitions) || !decodePayload(in, record) || !in.done()) {
        return false;
    }
    if (kind < 1 || kind > kLastKind || event > kLastEvent || flag > 1) {
        return false;
    }
    record.kind = static_cast<WireKind>(kind);
    record.event = static_cast<ResultEvent::Kind>(event);
    record.flag = flag != 0;
    record.message = TestMessage(message, detail, file, line);
    record.message.setDiagnostics(std::move(diagnostics));
    return true;
}

}  // namespace

WireRecord eventRecord(const ResultEvent& event, const std::string& name) {
    WireRecord record;
    record.kind = WireKind::Event;
    record.event = event.kind;
    record.name = name;
    record.message = event.message;
    record.flag = event.passed;
    record.repetition = event.repetition;
    record.repetitions = event.repetitions;
    record.measurement = event.measurement;
    record.attachment = event.attachment;
    return record;
}

ResultEvent eventOf(const WireRecord& record) {
    ResultEvent event;
    event.kind = record.event;
    event.testName = record.name;
    event.message = record.message;
    event.passed = record.flag;
    event.repetition = record.repetition;
    event.repetitions = record.repetitions;
    event.measurement = record.measurement;
    event.attachment = record.attachment;
    return event;
}

void encode(const WireRecord& record, std::string& out) {
    std::size_t start = out.size();
    putU32(out, 0);  // the length, filled in below
    out.push_back(static_cast<char>(record.kind));
    out.push_back(static_cast<char>(record.event));
    out.push_back(record.flag ? 1 : 0);
    putI64(out, record.number);
    putString(out, record.name);
    putString(out, record.message.getMessage());
    putString(out, record.message.getDetail());
    putString(out, record.message.getSourceFileName());
    putU32(out, record.message.getSourceLineNumber());
    // The message's diagnostics: their count, then each key and value.
    putU32(out, static_cast<std::uint32_t>(record.message.getDiagnostics().size()));
    for (const auto& [key, value] : record.message.getDiagnostics()) {
        putString(out, key);
        putString(out, value);
    }
    putU32(out, record.repetition);
    putU32(out, record.repetitions);
    putPayload(out, record);
    auto length = static_cast<std::uint32_t>(out.size() - start - 4);
    for (int i = 0; i < 4; ++i) {
        out[start + i] = static_cast<char>((length >> (8 * i)) & 0xff);
    }
}

std::string encode(const WireRecord& record) {
    std::string out;
    encode(record, out);
    return out;
}

WireDecoder::Status WireDecoder::next(WireRecord& record) {
    if (corrupt_) {
        return Status::Corrupt;
    }
    if (pending() < 4) {
        return Status::NeedMore;
    }
    Reader header(buffer_.data() + offset_, 4);
    std::uint32_t length = 0;
    header.u32(length);
    if (length > kMaxRecordSize) {
        corrupt_ = true;
        return Status::Corrupt;
    }
    if (pending() - 4 < length) {
        return Status::NeedMore;
    }
    if (!decodeBody(buffer_.data() + offset_ + 4, length, record)) {
        corrupt_ = true;
        return Status::Corrupt;
    }
    offset_ += 4 + length;
    // Drop consumed bytes now and then, not on every record.
    if (offset_ == buffer_.size()) {
        buffer_.clear();
        offset_ = 0;
    } else if (offset_ > 65536) {
        buffer_.erase(0, offset_);
        offset_ = 0;
    }
    return Status::Record;
}

std::string encodeRequest(const WorkRequest& request) {
    std::string out;
    out.push_back(static_cast<char>(request.role));
    putString(out, request.type);
    putString(out, request.path);
    putString(out, request.name);
    putString(out, request.param);
    putString(out, request.environment);
    putU32(out, request.repetition);
    putU32(out, static_cast<std::uint32_t>(request.variables.size()));
    for (const auto& variable : request.variables) {
        putString(out, variable);
    }
    return out;
}

bool decodeRequest(const std::string& data, WorkRequest& request) {
    Reader in(data.data(), data.size());
    std::uint8_t role;
    if (!in.u8(role) || !in.string(request.type) || !in.string(request.path) ||
        !in.string(request.name) || !in.string(request.param) || !in.string(request.environment) ||
        !in.u32(request.repetition)) {
        return false;
    }
    std::uint32_t count = 0;
    // Each variable takes at least 4 bytes: a count past what is left is garbage.
    if (!in.u32(count) || count > data.size() / 4) {
        return false;
    }
    request.variables.assign(count, std::string());
    for (auto& variable : request.variables) {
        if (!in.string(variable)) {
            return false;
        }
    }
    if (!in.done()) {
        return false;
    }
    if (role != static_cast<std::uint8_t>(WorkRequest::Role::Test) &&
        role != static_cast<std::uint8_t>(WorkRequest::Role::Fixture)) {
        return false;
    }
    request.role = static_cast<WorkRequest::Role>(role);
    return true;
}

std::string encodeSpareNote(SpareNote note, std::int64_t pid) {
    std::string out(1, static_cast<char>(note));
    putI64(out, pid);
    return out;
}

bool decodeSpareNote(const std::string& data, SpareNote& note, std::int64_t& pid) {
    Reader in(data.data(), data.size());
    std::uint8_t kind;
    if (!in.u8(kind) || !in.i64(pid) || !in.done() ||
        (kind != static_cast<std::uint8_t>(SpareNote::Announced) &&
         kind != static_cast<std::uint8_t>(SpareNote::Claimed))) {
        return false;
    }
    note = static_cast<SpareNote>(kind);
    return true;
}

}  // namespace isolation
}  // namespace robottestingframework
