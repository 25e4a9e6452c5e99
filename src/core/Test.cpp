#include <robottestingframework/Test.h>

#include <utility>

namespace robottestingframework {

Test::Test(std::string name, std::string description)
    : name_(std::move(name)), description_(std::move(description)) {}

Test::~Test() = default;

}  // namespace robottestingframework
