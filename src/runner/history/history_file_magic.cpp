// How a history file looks from outside: the same in a build with SQLite and without.
#include <cstring>
#include <filesystem>
#include <fstream>

#include "platform/file_kind.h"
#include "runner/history/history_database.h"
#include "runner/history/history_error.h"

namespace robottestingframework {
namespace runner {

void checkHistoryFileKind(const std::string& path) {
    using std::filesystem::file_type;
    std::error_code failed;
    const file_type type = std::filesystem::status(path, failed).type();
    if (failed || type == file_type::not_found || type == file_type::regular) {
        return;  // what cannot be looked at is told by SQLite's own error when opened
    }
    throw HistoryError("--history " + path + ": is " + platform::fileKindText(type) +
                       ", not a history file (a history file is a regular file, an SQLite "
                       "database, created when missing)");
}

bool looksLikeHistoryFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[16] = {};
    in.read(magic, sizeof(magic));
    return in.gcount() == sizeof(magic) && std::memcmp(magic, "SQLite format 3", 16) == 0;
}

}  // namespace runner
}  // namespace robottestingframework
