// Windows: the loaders not built for Windows yet (README: Platforms), each saying so.
#include "languages/language_loaders.h"

namespace robottestingframework {
namespace languages {

std::unique_ptr<LoadedFixture> loadProcessFixture(const std::string& path, std::string& error) {
    error = "'" + path + "': the process fixture is not built for Windows yet";
    return nullptr;
}

}  // namespace languages
}  // namespace robottestingframework
