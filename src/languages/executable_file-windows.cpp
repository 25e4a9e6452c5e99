#include "languages/executable_file.h"

#include <windows.h>

#include <cstring>

namespace robottestingframework {
namespace languages {

bool isExecutableFile(const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
        return false;
    }
    const std::string extension = path.substr(dot);
    bool program = false;
    for (const char* known : {".exe", ".com", ".bat", ".cmd"}) {
        program = program || ::_stricmp(extension.c_str(), known) == 0;
    }
    const DWORD attributes = ::GetFileAttributesA(path.c_str());
    return program && attributes != INVALID_FILE_ATTRIBUTES &&
           (attributes & FILE_ATTRIBUTE_DIRECTORY) == 0;
}

}  // namespace languages
}  // namespace robottestingframework
