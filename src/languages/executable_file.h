// Whether a file is a program an exec test runs: on POSIX a regular file with the execute
// permission; on Windows an .exe, .com, .bat or .cmd file (Windows has no such permission).
#pragma once

#include <string>

namespace robottestingframework {
namespace languages {

bool isExecutableFile(const std::string& path);

}  // namespace languages
}  // namespace robottestingframework
