#include <robottestingframework/TestMessage.h>

#include <utility>

namespace robottestingframework {

TestMessage::TestMessage(std::string message, std::string detail, std::string filename,
                         unsigned int line)
    : message_(std::move(message)),
      detail_(std::move(detail)),
      filename_(std::move(filename)),
      line_(line) {}

TestMessage::TestMessage(const TestMessage& other)
    : message_(other.message_),
      detail_(other.detail_),
      filename_(other.filename_),
      line_(other.line_),
      diagnostics_(other.diagnostics_ ? std::make_unique<Diagnostics>(*other.diagnostics_)
                                      : nullptr) {}

TestMessage& TestMessage::operator=(const TestMessage& other) {
    if (this != &other) {
        TestMessage copy(other);
        *this = std::move(copy);
    }
    return *this;
}

void TestMessage::setDiagnostics(Diagnostics diagnostics) {
    diagnostics_ =
        diagnostics.empty() ? nullptr : std::make_unique<Diagnostics>(std::move(diagnostics));
}

const TestMessage::Diagnostics& TestMessage::getDiagnostics() const {
    static const Diagnostics none;
    return diagnostics_ ? *diagnostics_ : none;
}

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

std::string TestMessage::diagnosticsText() const {
    std::string text;
    for (const auto& [key, value] : getDiagnostics()) {
        if (value.find('\n') == std::string::npos) {
            text += key + ": " + value + "\n";
            continue;
        }
        text += key + ":\n";
        std::size_t begin = 0;
        while (begin < value.size()) {
            std::size_t end = value.find('\n', begin);
            end = end == std::string::npos ? value.size() : end;
            text += "  " + value.substr(begin, end - begin) + "\n";
            begin = end + 1;
        }
    }
    return text;
}

void TestMessage::clear() {
    message_.clear();
    detail_.clear();
    filename_.clear();
    line_ = 0;
    diagnostics_.reset();
}

}  // namespace robottestingframework
