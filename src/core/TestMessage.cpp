#include <robottestingframework/TestMessage.h>

#include <utility>

namespace robottestingframework {

TestMessage::TestMessage(std::string message, std::string detail, std::string filename,
                         unsigned int line)
    : message_(std::move(message)),
      detail_(std::move(detail)),
      filename_(std::move(filename)),
      line_(line) {}

std::string TestMessage::getSourceLocation() const {
    if (filename_.empty()) {
        return {};
    }
    return filename_ + ":" + std::to_string(line_);
}

std::string TestMessage::toString() const {
    if (detail_.empty()) {
        return message_;
    }
    if (message_.empty()) {
        return detail_;
    }
    return message_ + ": " + detail_;
}

void TestMessage::clear() {
    message_.clear();
    detail_.clear();
    filename_.clear();
    line_ = 0;
}

}  // namespace robottestingframework
