// A message attached to a test event: what happened, more detail, and where in the source.
#pragma once

#include <string>

namespace robottestingframework {

class TestMessage {
public:
    TestMessage() = default;
    TestMessage(std::string message, std::string detail = "", std::string filename = "",
                unsigned int line = 0);

    void setMessage(const std::string& message) { message_ = message; }
    void setDetail(const std::string& detail) { detail_ = detail; }
    void setSourceFileName(const std::string& filename) { filename_ = filename; }
    void setSourceLineNumber(unsigned int line) { line_ = line; }

    std::string getMessage() const { return message_; }
    std::string getDetail() const { return detail_; }
    std::string getSourceFileName() const { return filename_; }
    unsigned int getSourceLineNumber() const { return line_; }

    // "file:line" when the source is known, empty otherwise.
    std::string getSourceLocation() const;
    // message, then ": detail" when there is one.
    std::string toString() const;

    void clear();

private:
    std::string message_;
    std::string detail_;
    std::string filename_;
    unsigned int line_ = 0;
};

}  // namespace robottestingframework
