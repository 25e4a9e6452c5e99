// A message attached to a test event: what happened, more detail, and where in the source.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace robottestingframework {

class TestMessage {
public:
    // Structured diagnostics beside the text, in the order given: each a key and its value as
    // text (a TAP point's YAML block: `got: 3`, `wanted: 4`, `at:` with its lines). Reports show
    // them as a block of their own under the message, never in its one-line text.
    using Diagnostics = std::vector<std::pair<std::string, std::string>>;

    TestMessage() = default;
    TestMessage(std::string message, std::string detail = "", std::string filename = "",
                unsigned int line = 0);
    // Copies the diagnostics too (held apart, so a message without any, nearly every one,
    // costs a pointer: a run keeps one message per event).
    TestMessage(const TestMessage& other);
    TestMessage& operator=(const TestMessage& other);
    TestMessage(TestMessage&&) noexcept = default;
    TestMessage& operator=(TestMessage&&) noexcept = default;
    ~TestMessage() = default;

    void setMessage(const std::string& message) { message_ = message; }
    void setDetail(const std::string& detail) { detail_ = detail; }
    void setSourceFileName(const std::string& filename) { filename_ = filename; }
    void setSourceLineNumber(unsigned int line) { line_ = line; }
    void setDiagnostics(Diagnostics diagnostics);

    std::string getMessage() const { return message_; }
    std::string getDetail() const { return detail_; }
    std::string getSourceFileName() const { return filename_; }
    unsigned int getSourceLineNumber() const { return line_; }
    const Diagnostics& getDiagnostics() const;

    // "file:line" when the source is known, empty otherwise.
    std::string getSourceLocation() const;
    // message, then ": detail" when there is one (never the diagnostics).
    std::string toString() const;
    // The diagnostics as YAML-like lines, each ending in '\n': "key: value", or "key:" then the
    // value's lines indented by two spaces when it spans lines; "" without any.
    std::string diagnosticsText() const;

    void clear();

private:
    std::string message_;
    std::string detail_;
    std::string filename_;
    unsigned int line_ = 0;
    std::unique_ptr<Diagnostics> diagnostics_;  // null: none
};

}  // namespace robottestingframework
