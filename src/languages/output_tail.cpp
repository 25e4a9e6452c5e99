#include "languages/output_tail.h"

namespace robottestingframework {
namespace languages {

void OutputTail::append(const char* data, std::size_t size) {
    if (size >= limit_) {
        // Only its end can be kept.
        dropped_ += text_.size() + size - limit_;
        text_.assign(data + size - limit_, limit_);
        return;
    }
    text_.append(data, size);
    if (text_.size() > limit_ + limit_ / 2) {
        // Trim in chunks, not on every append.
        std::size_t cut = text_.size() - limit_;
        dropped_ += cut;
        text_.erase(0, cut);
    }
}

std::string OutputTail::take() {
    if (text_.size() > limit_) {
        dropped_ += text_.size() - limit_;
        text_.erase(0, text_.size() - limit_);
    }
    std::string text;
    if (dropped_ > 0) {
        text = "[... " + std::to_string(dropped_) + " bytes of earlier output dropped ...]\n";
    }
    text += text_;
    text_.clear();
    dropped_ = 0;
    return text;
}

}  // namespace languages
}  // namespace robottestingframework
