#include <robottestingframework/Exception.h>

namespace robottestingframework {

Exception::Exception(const TestMessage& message) : message_(message), what_(message.toString()) {
    const std::string where = message.getSourceLocation();
    if (!where.empty()) {
        what_ += " (" + where + ")";
    }
}

const char* Exception::what() const noexcept {
    return what_.c_str();
}

}  // namespace robottestingframework
