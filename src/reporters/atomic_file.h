// Writing a report file whole or not at all: a temporary name beside it, then a rename.
#pragma once

#include <string>

namespace robottestingframework {
namespace reporters {

// On failure returns false, leaves no file behind and puts the file name and the system's
// reason in `error`.
bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error);

}  // namespace reporters
}  // namespace robottestingframework
