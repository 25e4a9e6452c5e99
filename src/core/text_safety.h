// Test text is data: whatever bytes a test prints, every output stays a well-formed file.
#pragma once

#include <cstddef>
#include <string>

namespace robottestingframework {
namespace reporters {

// Length of the valid UTF-8 sequence starting at s[i] (a byte of 0x80 or more) that XML 1.0
// allows; 0 when there is none (a stray byte, an overlong form, a surrogate, U+FFFE/U+FFFF).
std::size_t validSequence(const std::string& s, std::size_t i);
// `at`, moved back to the first byte of the UTF-8 character it falls inside: where `text` may
// be cut without splitting a character. `at` itself when it is past the end.
std::size_t characterBoundary(const std::string& text, std::size_t at);
// `text` with every byte that does not start such a sequence replaced by U+FFFD.
std::string validUtf8(const std::string& text);
// `text` as a plain text file should hold it: invalid UTF-8 replaced as validUtf8 does, and
// control characters other than tab, newline and carriage return (a NUL, an escape) dropped.
std::string plainText(const std::string& text);
// `text` as a terminal or a plain text report shows it without obeying it (a name or a message
// of a test must not clear the screen, retitle the window or fake a line): invalid UTF-8
// replaced as validUtf8 does, and every control character but tab (C0, DEL, C1) written as an
// escape one can read: \r, \n, \e, \xNN (\u0085 and the like for C1). With `continuation`,
// line breaks stay, and each line after the first starts with `continuation`. `text` itself
// when it has nothing to escape.
std::string visibleText(const std::string& text, const char* continuation = nullptr);
// `text` as a quoted JSON string: invalid UTF-8 replaced, control characters escaped, and `<`,
// `>` and `&` as \u escapes so the literal stays inert inside an HTML <script>.
std::string jsonString(const std::string& text);

// Where escapeMarkup's result goes.
enum class Markup {
    Text,       // XML or HTML element content: `&`, `<`, `>` as entities
    Quoted,     // content that may end up inside quotes: `"` and `'` as entities too
    Attribute,  // a "-quoted attribute value: `"` as an entity, and tab and newline as
                // character references so that attribute normalisation keeps them
};
// `text` as XML 1.0 / HTML text for `where`: markup characters as entities, and what XML 1.0
// cannot hold (control characters other than tab, newline and carriage return, bytes that are
// not valid UTF-8) dropped. The one escaping of the JUnit report and the web page's log.
std::string escapeMarkup(const std::string& text, Markup where);

// `name` as a file name every report can link and Jenkins' [[ATTACHMENT|...]] line can hold
// (docs/how-to/measurements-and-attachments.md): control characters, bytes that are not UTF-8, `[`,
// `]`, `|` and what Windows refuses in a name (`<`, `>`, `:`, `"`, `\`, `?`, `*`) each become `_`.
std::string safeFileName(const std::string& name);

}  // namespace reporters
}  // namespace robottestingframework
