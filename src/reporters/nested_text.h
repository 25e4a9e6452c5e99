// Text made of nested blocks, each line indented four spaces per level (a TAP subtest inside
// its parent), kept as pieces: a block that closes moves its pieces into its parent one level
// deeper instead of being copied line by line, and no piece grows past a bound. A report of
// 10 000 tests thus holds its text once, not twice at the moment a suite closes, nor with the
// slack of one string doubling (issue 22: the TAP body was most of the runner's peak).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "reporters/reporter.h"

namespace robottestingframework {
namespace reporters {

class NestedText {
public:
    // Appends at this block's own level.
    NestedText& operator+=(std::string_view text);
    // Moves `inner`'s text (whole lines) after this one's, one level deeper; `inner` is empty
    // afterwards.
    void appendNested(NestedText&& inner);
    // Bytes appended so far, indentation not counted.
    std::size_t size() const { return size_; }
    // Drops what came after the first `size` bytes (a point taken back).
    void truncate(std::size_t size);
    // The text with its indentation.
    void writeTo(ReportText& out) const;
    std::string str() const;

    // A piece stops growing at this size: the next text starts a new one.
    static constexpr std::size_t pieceSize = 64 * 1024;

private:
    struct Piece {
        unsigned int depth = 0;
        std::string text;
    };
    std::vector<Piece> pieces_;
    std::size_t size_ = 0;
};

}  // namespace reporters
}  // namespace robottestingframework
