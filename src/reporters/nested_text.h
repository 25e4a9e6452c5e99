// Text made of nested blocks, each line indented four spaces per level (a TAP subtest inside
// its parent), kept as pieces: a block that closes moves its pieces into its parent one level
// deeper instead of being copied line by line, and no piece grows past a bound. A report of
// 10 000 tests thus holds its text once, not twice at the moment a suite closes, nor with the
// slack of one string doubling (issue 22: the TAP body was most of the runner's peak).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
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
    // Marks the end of the text so far (a line's end) as the place of lines the writer gives
    // only when the text is written: TAP writes a test's measurements there from the
    // collector's records rather than holding their YAML for the whole run.
    void markLines(std::uint64_t id);
    // Gives, into `text`, the lines of a mark (unindented, each ending in a newline).
    using MarkWriter = std::function<void(std::uint64_t id, std::string& text)>;
    // The text with its indentation; each mark's lines from `marks` (none without).
    void writeTo(ReportText& out, const MarkWriter& marks = nullptr) const;
    std::string str() const;

    // A piece stops growing at this size: the next text starts a new one.
    static constexpr std::size_t pieceSize = 64 * 1024;

private:
    struct Piece {
        unsigned int depth = 0;
        std::string text;
    };
    // Lines written at `at` bytes (indentation not counted), in order.
    struct Mark {
        std::size_t at;
        std::uint64_t id;
    };
    std::vector<Piece> pieces_;
    std::vector<Mark> marks_;
    std::size_t size_ = 0;
};

}  // namespace reporters
}  // namespace robottestingframework
