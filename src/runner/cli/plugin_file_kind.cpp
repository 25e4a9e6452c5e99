#include "runner/cli/plugin_file_kind.h"

#include <algorithm>
#include <fstream>
#include <string>

namespace robottestingframework {
namespace runner {

namespace {

// The factories' names as the file's string table holds them (ELF .dynstr, PE export names;
// Mach-O adds a leading underscore, which the search does not need).
const std::string testFactory = "robottestingframework_dll_factory";
const std::string fixtureFactory = "robottestingframework_fixture_factory";

}  // namespace

PluginFileKind pluginFileKind(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return PluginFileKind::Other;
    }
    // Read in blocks; each block starts with the previous one's last bytes so a name cut by a
    // block's end is found in the next.
    const std::size_t overlap = std::max(testFactory.size(), fixtureFactory.size());
    const std::size_t blockSize = 1 << 20;
    std::string block;
    bool fixture = false;
    while (in) {
        const std::size_t kept = block.size() < overlap ? block.size() : overlap;
        block.erase(0, block.size() - kept);
        block.resize(kept + blockSize);
        in.read(&block[kept], static_cast<std::streamsize>(blockSize));
        block.resize(kept + static_cast<std::size_t>(in.gcount()));
        if (block.find(testFactory) != std::string::npos) {
            return PluginFileKind::Test;
        }
        fixture = fixture || block.find(fixtureFactory) != std::string::npos;
    }
    return fixture ? PluginFileKind::Fixture : PluginFileKind::Other;
}

}  // namespace runner
}  // namespace robottestingframework
