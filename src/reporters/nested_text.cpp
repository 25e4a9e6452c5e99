#include "reporters/nested_text.h"

#include <utility>

namespace robottestingframework {
namespace reporters {

NestedText& NestedText::operator+=(std::string_view text) {
    if (text.empty()) {
        return *this;
    }
    if (pieces_.empty() || pieces_.back().depth != 0 ||
        pieces_.back().text.size() + text.size() > pieceSize) {
        pieces_.emplace_back();
    }
    pieces_.back().text.append(text.data(), text.size());
    size_ += text.size();
    return *this;
}

void NestedText::markLines(std::uint64_t id) {
    marks_.push_back({size_, id});
}

void NestedText::appendNested(NestedText&& inner) {
    for (const Mark& mark : inner.marks_) {
        marks_.push_back({size_ + mark.at, mark.id});
    }
    inner.marks_.clear();
    pieces_.reserve(pieces_.size() + inner.pieces_.size());
    for (Piece& piece : inner.pieces_) {
        ++piece.depth;
        size_ += piece.text.size();
        pieces_.push_back(std::move(piece));
    }
    inner.pieces_.clear();
    inner.size_ = 0;
}

void NestedText::truncate(std::size_t size) {
    // A mark at `size` itself was made before the text taken back began (a point's lines
    // follow its "ok" line), so it stays.
    while (!marks_.empty() && marks_.back().at > size) {
        marks_.pop_back();
    }
    while (size_ > size && !pieces_.empty()) {
        std::string& last = pieces_.back().text;
        const std::size_t excess = size_ - size;
        if (excess >= last.size()) {
            size_ -= last.size();
            pieces_.pop_back();
        } else {
            last.resize(last.size() - excess);
            size_ = size;
        }
    }
}

void NestedText::writeTo(ReportText& out, const MarkWriter& marks) const {
    static const std::string spaces(64, ' ');
    bool lineStart = true;
    // Writes `text` at `depth`, each line indented.
    const auto write = [&](std::string_view text, unsigned int depth) {
        std::size_t begin = 0;
        while (begin < text.size()) {
            if (lineStart) {
                for (std::size_t left = 4 * std::size_t{depth}; left > 0;) {
                    const std::size_t n = left < spaces.size() ? left : spaces.size();
                    out += std::string_view(spaces.data(), n);
                    left -= n;
                }
            }
            std::size_t end = text.find('\n', begin);
            lineStart = end != std::string_view::npos;
            end = lineStart ? end + 1 : text.size();
            out += text.substr(begin, end - begin);
            begin = end;
        }
    };
    std::size_t at = 0;  // bytes written so far, indentation not counted
    std::size_t nextMark = 0;
    std::string lines;
    // The marks at `at`, each written at `depth` (the depth of the text before it).
    const auto writeMarks = [&](unsigned int depth) {
        for (; nextMark < marks_.size() && marks_[nextMark].at == at; ++nextMark) {
            if (marks) {
                lines.clear();
                marks(marks_[nextMark].id, lines);
                write(lines, depth);
            }
        }
    };
    for (const Piece& piece : pieces_) {
        std::string_view text = piece.text;
        if (at == 0) {
            writeMarks(piece.depth);  // marks before any text
        }
        while (!text.empty()) {
            // The piece up to the next mark inside it (or its end).
            std::size_t take = text.size();
            if (nextMark < marks_.size() && marks_[nextMark].at > at &&
                marks_[nextMark].at - at < take) {
                take = marks_[nextMark].at - at;
            }
            write(text.substr(0, take), piece.depth);
            text.remove_prefix(take);
            at += take;
            writeMarks(piece.depth);
        }
    }
}

std::string NestedText::str() const {
    WholeReportText text;
    writeTo(text);
    return text.take();
}

}  // namespace reporters
}  // namespace robottestingframework
