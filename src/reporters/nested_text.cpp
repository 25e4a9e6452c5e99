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

void NestedText::appendNested(NestedText&& inner) {
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

void NestedText::writeTo(ReportText& out) const {
    static const std::string spaces(64, ' ');
    bool lineStart = true;
    for (const Piece& piece : pieces_) {
        const std::string_view text = piece.text;
        std::size_t begin = 0;
        while (begin < text.size()) {
            if (lineStart) {
                for (std::size_t left = 4 * std::size_t{piece.depth}; left > 0;) {
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
    }
}

std::string NestedText::str() const {
    WholeReportText text;
    writeTo(text);
    return text.take();
}

}  // namespace reporters
}  // namespace robottestingframework
