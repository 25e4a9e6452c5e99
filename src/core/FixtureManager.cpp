#include <robottestingframework/FixtureManager.h>

#include <robottestingframework/Arguments.h>

#include <utility>

namespace robottestingframework {

FixtureManager::FixtureManager(FixtureEvents* dispatcher, std::string param)
    : dispatcher_(dispatcher), param_(std::move(param)) {}

FixtureManager::FixtureManager(std::string param) : FixtureManager(nullptr, std::move(param)) {}

FixtureManager::~FixtureManager() = default;

bool FixtureManager::setup() {
    ArgumentVector args(param_);
    return setup(args.argc(), args.argv());
}

bool FixtureManager::setup(int /*argc*/, char** /*argv*/) {
    return true;
}

void FixtureManager::setResult(TestResult* result, const Test* owner) {
    result_ = result;
    owner_ = owner;
}

}  // namespace robottestingframework
