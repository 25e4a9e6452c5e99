// Test text is data: whatever bytes a test prints, every output stays a well-formed file.
#pragma once

#include <cstddef>
#include <string>

namespace robottestingframework {
namespace reporters {

// Length of the valid UTF-8 sequence starting at s[i] (a byte of 0x80 or more) that XML 1.0
// allows; 0 when there is none (a stray byte, an overlong form, a surrogate, U+FFFE/U+FFFF).
std::size_t validSequence(const std::string& s, std::size_t i);
// `text` with every byte that does not start such a sequence replaced by U+FFFD.
std::string validUtf8(const std::string& text);
// `text` as a quoted JSON string: invalid UTF-8 replaced, control characters escaped, and `<`,
// `>` and `&` as \u escapes so the literal stays inert inside an HTML <script>.
std::string jsonString(const std::string& text);

}  // namespace reporters
}  // namespace robottestingframework
