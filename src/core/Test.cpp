#include <robottestingframework/Test.h>

#include <string>
#include <utility>

#include <robottestingframework/TestResult.h>

#include "core/text_safety.h"

namespace robottestingframework {

Test::Test(std::string name, std::string description)
    : name_(std::move(name)), description_(std::move(description)) {}

Test::~Test() = default;

namespace {
std::atomic<std::uint64_t> lastId{0};
}  // namespace

std::uint64_t Test::getId() const {
    std::uint64_t id = id_.load(std::memory_order_acquire);
    if (id == 0) {
        // Given once, even when two threads ask at the same time.
        std::uint64_t fresh = lastId.fetch_add(1, std::memory_order_relaxed) + 1;
        if (id_.compare_exchange_strong(id, fresh, std::memory_order_acq_rel)) {
            id = fresh;
        }
    }
    return id;
}

namespace {

// A name longer than this is cut, saying so (README: Output limits): a test that renames itself
// to megabytes, and again, fills neither the runner's memory nor every report. The cut falls
// on a character's first byte.
constexpr std::size_t maxName = 4096;

std::string bounded(std::string name) {
    if (name.size() <= maxName) {
        return name;
    }
    const std::size_t keep = reporters::characterBoundary(name, maxName);
    const std::size_t dropped = name.size() - keep;
    name.resize(keep);
    return name + " [... " + std::to_string(dropped) + " more bytes of this name dropped]";
}

}  // namespace

void Test::setName(std::string name) {
    name = bounded(std::move(name));
    // Swapped, not assigned: a short name moved into a long one's string keeps the long one's
    // memory (the runner's 10 000 stand-ins, named by their plug-in's path until the test case
    // names itself, kept 48 bytes each). The old text goes with `name`.
    const bool renamed = renames_ != nullptr && name != name_;
    name_.swap(name);
    if (renamed) {
        renames_->renameTest(this, name_);
    }
}

}  // namespace robottestingframework
