// How a history file looks from outside: the same in a build with SQLite and without.
#include <cstring>
#include <fstream>

#include "runner/history/history_database.h"

namespace robottestingframework {
namespace runner {

bool looksLikeHistoryFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[16] = {};
    in.read(magic, sizeof(magic));
    return in.gcount() == sizeof(magic) && std::memcmp(magic, "SQLite format 3", 16) == 0;
}

}  // namespace runner
}  // namespace robottestingframework
