#include <robottestingframework/Test.h>

#include <utility>

#include <robottestingframework/TestResult.h>

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

void Test::setName(std::string name) {
    if (renames_ == nullptr || name == name_) {
        name_ = std::move(name);
        return;
    }
    name_ = std::move(name);
    renames_->renameTest(this, name_);
}

}  // namespace robottestingframework
