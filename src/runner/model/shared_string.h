// A string that every part of the model saying the same thing holds once: the plug-in path of a
// suite's 10 000 tests, the suite file they were read from. A copy is a pointer and a count, not
// the text (issue 23: the specs of 10 000 tests held the same path four times each). Immutable:
// assigning a new text makes a new string, the others keep theirs.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <unordered_map>

namespace robottestingframework {
namespace runner {

class SharedString {
public:
    SharedString() = default;
    // Implicit, like the std::string it replaces in the model: `spec.plugin = "libx.so"`.
    SharedString(std::string text);
    SharedString(const char* text) : SharedString(std::string(text)) {}

    const std::string& str() const { return text_ ? *text_ : empty_; }
    operator const std::string&() const { return str(); }
    const char* c_str() const { return str().c_str(); }
    bool empty() const { return str().empty(); }
    std::size_t size() const { return str().size(); }

    // True when both hold the very same string, not only equal texts (the tests of sharing).
    bool sharesWith(const SharedString& other) const { return text_ && text_ == other.text_; }

private:
    static const std::string empty_;
    std::shared_ptr<const std::string> text_;
};

// Hands out one SharedString per distinct text: what a suite reader gives every test of a suite
// that names the same plug-in, or every element of one file.
class StringPool {
public:
    SharedString intern(const std::string& text);

private:
    std::unordered_map<std::string, SharedString> strings_;
};

inline bool operator==(const SharedString& a, const SharedString& b) {
    return a.str() == b.str();
}
inline bool operator==(const SharedString& a, const std::string& b) {
    return a.str() == b;
}
inline bool operator==(const std::string& a, const SharedString& b) {
    return a == b.str();
}
inline bool operator==(const SharedString& a, const char* b) {
    return a.str() == b;
}
inline bool operator!=(const SharedString& a, const SharedString& b) {
    return !(a == b);
}
inline bool operator!=(const SharedString& a, const std::string& b) {
    return !(a == b);
}
inline bool operator!=(const std::string& a, const SharedString& b) {
    return !(a == b);
}
inline bool operator!=(const SharedString& a, const char* b) {
    return !(a == b);
}

inline std::string operator+(const std::string& a, const SharedString& b) {
    return a + b.str();
}
inline std::string operator+(const char* a, const SharedString& b) {
    return a + b.str();
}
inline std::string operator+(const SharedString& a, const std::string& b) {
    return a.str() + b;
}
inline std::string operator+(const SharedString& a, const char* b) {
    return a.str() + b;
}

inline std::ostream& operator<<(std::ostream& out, const SharedString& text) {
    return out << text.str();
}

}  // namespace runner
}  // namespace robottestingframework
