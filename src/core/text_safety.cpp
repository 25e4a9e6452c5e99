#include "core/text_safety.h"

#include <algorithm>
#include <cstdio>

namespace robottestingframework {
namespace reporters {

std::size_t characterBoundary(const std::string& text, std::size_t at) {
    if (at >= text.size()) {
        return at;
    }
    while (at > 0 && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) {
        --at;
    }
    return at;
}

std::size_t validSequence(const std::string& s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    unsigned char low = 0x80;
    unsigned char high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        if (lead == 0xE0) {
            low = 0xA0;  // overlong
        } else if (lead == 0xED) {
            high = 0x9F;  // surrogates
        }
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        if (lead == 0xF0) {
            low = 0x90;
        } else if (lead == 0xF4) {
            high = 0x8F;
        }
    } else {
        return 0;
    }
    if (i + length > s.size() || byte(i + 1) < low || byte(i + 1) > high) {
        return 0;
    }
    for (std::size_t k = 2; k < length; ++k) {
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) {
            return 0;
        }
    }
    // U+FFFE and U+FFFF are not XML characters.
    if (length == 3 && lead == 0xEF && byte(i + 1) == 0xBF && byte(i + 2) >= 0xBE) {
        return 0;
    }
    return length;
}

std::string validUtf8(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        const std::size_t length = validSequence(text, i);
        if (length == 0) {
            out += "\xEF\xBF\xBD";  // U+FFFD, the replacement character
            ++i;
        } else {
            out.append(text, i, length);
            i += length;
        }
    }
    return out;
}

std::string plainText(const std::string& text) {
    std::string out = validUtf8(text);
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](char ch) {
                                 const auto c = static_cast<unsigned char>(ch);
                                 return (c < 0x20 && c != '\t' && c != '\n' && c != '\r') ||
                                        c == 0x7F;
                             }),
              out.end());
    return out;
}

std::string visibleText(const std::string& text, const char* continuation) {
    const bool clean = std::all_of(text.begin(), text.end(), [](char ch) {
        const auto c = static_cast<unsigned char>(ch);
        return (c >= 0x20 && c < 0x7F) || c == '\t';
    });
    if (clean) {
        return text;  // most names and messages: nothing to copy byte by byte
    }
    const std::string valid = validUtf8(text);
    std::string out;
    out.reserve(valid.size() + 16);
    for (std::size_t i = 0; i < valid.size(); ++i) {
        const auto c = static_cast<unsigned char>(valid[i]);
        if (c == '\n' && continuation != nullptr) {
            out += '\n';
            out += continuation;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == 0x1B) {
            out += "\\e";
        } else if ((c < 0x20 && c != '\t') || c == 0x7F) {
            char escaped[8];
            std::snprintf(escaped, sizeof(escaped), "\\x%02x", c);
            out += escaped;
        } else if (c == 0xC2 && i + 1 < valid.size() &&
                   static_cast<unsigned char>(valid[i + 1]) < 0xA0) {
            // U+0080..U+009F: C1 controls (U+009B starts a sequence as ESC [ does).
            char escaped[8];
            std::snprintf(escaped, sizeof(escaped), "\\u%04x",
                          static_cast<unsigned char>(valid[i + 1]));
            out += escaped;
            ++i;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

std::string jsonString(const std::string& text) {
    const std::string valid = validUtf8(text);
    std::string out;
    out.reserve(valid.size() + 2);
    out += '"';
    for (const char ch : valid) {
        const unsigned char c = static_cast<unsigned char>(ch);
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (c < 0x20 || c == 0x7F || c == '<' || c == '>' || c == '&') {
                    char escaped[8];
                    std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
                    out += escaped;
                } else {
                    out += ch;
                }
        }
    }
    out += '"';
    return out;
}

std::string escapeMarkup(const std::string& text, Markup where) {
    const bool attribute = where == Markup::Attribute;
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x80) {
            const std::size_t length = validSequence(text, i);
            if (length == 0) {
                ++i;
            } else {
                out.append(text, i, length);
                i += length;
            }
            continue;
        }
        ++i;
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += where == Markup::Text ? "\"" : "&quot;";
                break;
            case '\'':
                out += where == Markup::Quoted ? "&#39;" : "'";
                break;
            case '\r':
                out += "&#13;";
                break;
            case '\n':
                out += attribute ? "&#10;" : "\n";
                break;
            case '\t':
                out += attribute ? "&#9;" : "\t";
                break;
            default:
                if (c >= 0x20) {
                    out += static_cast<char>(c);
                }
        }
    }
    return out;
}

std::string safeFileName(const std::string& name) {
    std::string safe;
    safe.reserve(name.size());
    for (std::size_t i = 0; i < name.size();) {
        const auto c = static_cast<unsigned char>(name[i]);
        if (c >= 0x80) {
            const std::size_t length = validSequence(name, i);
            if (length == 0) {
                safe += '_';
                ++i;
            } else {
                safe.append(name, i, length);
                i += length;
            }
            continue;
        }
        const bool unsafe = c < 0x20 || c == 0x7F || c == '[' || c == ']' || c == '|' || c == '<' ||
                            c == '>' || c == ':' || c == '"' || c == '\\' || c == '?' || c == '*';
        safe += unsafe ? '_' : static_cast<char>(c);
        ++i;
    }
    return safe;
}

}  // namespace reporters
}  // namespace robottestingframework
