// shlibpp's four-character codes (RTF 2.x's dll/Vocab.h): up to four characters packed into an
// int, first character in the lowest byte, so codes read well in a debugger and switch fast.
#pragma once

#include <cstdint>
#include <string>

namespace shlibpp {

constexpr std::int32_t VOCAB(char a, char b = 0, char c = 0, char d = 0) {
    return static_cast<std::int32_t>(
        static_cast<std::uint32_t>(static_cast<unsigned char>(a)) |
        static_cast<std::uint32_t>(static_cast<unsigned char>(b)) << 8 |
        static_cast<std::uint32_t>(static_cast<unsigned char>(c)) << 16 |
        static_cast<std::uint32_t>(static_cast<unsigned char>(d)) << 24);
}

class Vocab {
public:
    // The code of the first four characters of `text` (fewer give zero bytes).
    static int encode(const std::string& text) {
        char chars[4] = {0, 0, 0, 0};
        for (std::size_t i = 0; i < text.size() && i < 4; ++i) {
            chars[i] = text[i];
        }
        return VOCAB(chars[0], chars[1], chars[2], chars[3]);
    }

    // The characters of `code`, zero bytes left out.
    static std::string decode(int code) {
        std::string text;
        auto bits = static_cast<std::uint32_t>(code);
        for (int i = 0; i < 4; ++i, bits >>= 8) {
            if ((bits & 0xffu) != 0) {
                text += static_cast<char>(bits & 0xffu);
            }
        }
        return text;
    }
};

}  // namespace shlibpp
