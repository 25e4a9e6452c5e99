// The last bytes a test printed, bounded so that a chatty test cannot fill the memory of the
// process that collects them (the runner for a worker, a worker for an exec test's program).
#pragma once

#include <cstddef>
#include <string>

namespace robottestingframework {
namespace languages {

// What a test's output is cut to in the reports.
constexpr std::size_t kOutputTail = 64 * 1024;

class OutputTail {
public:
    explicit OutputTail(std::size_t limit = kOutputTail) : limit_(limit) {}
    void append(const char* data, std::size_t size);
    void append(const std::string& bytes) { append(bytes.data(), bytes.size()); }
    bool empty() const { return text_.empty() && dropped_ == 0; }
    // Bytes dropped so far (before the kept tail).
    std::size_t dropped() const { return dropped_; }
    // What is kept, marked when earlier output was dropped; then forgets it.
    std::string take();

private:
    std::size_t limit_;
    std::string text_;
    std::size_t dropped_ = 0;
};

}  // namespace languages
}  // namespace robottestingframework
