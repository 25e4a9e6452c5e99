// loadFixture("process", world file): the built-in process fixture (src/fixtures/process).
#include <memory>
#include <string>
#include <utility>

#include "fixtures/process/process_fixture.h"
#include "languages/language_loaders.h"

namespace robottestingframework {
namespace languages {

namespace {

class LoadedProcessFixture : public LoadedFixture {
public:
    explicit LoadedProcessFixture(std::unique_ptr<fixtures::ProcessFixture> fixture)
        : fixture_(std::move(fixture)) {}
    FixtureManager* get() override { return fixture_.get(); }
    void interrupt() override { fixture_->interrupt(); }

private:
    std::unique_ptr<fixtures::ProcessFixture> fixture_;
};

}  // namespace

std::unique_ptr<LoadedFixture> loadProcessFixture(const std::string& path, std::string& error) {
    auto fixture = fixtures::makeProcessFixture(path, error);
    if (!fixture) {
        return nullptr;
    }
    return std::make_unique<LoadedProcessFixture>(std::move(fixture));
}

}  // namespace languages
}  // namespace robottestingframework
