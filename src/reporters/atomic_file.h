// Writing a report file whole or not at all: a temporary name beside it, then a rename.
#pragma once

#include <string>

#include <robottestingframework/TestMessage.h>

namespace robottestingframework {
namespace reporters {

// On failure returns false, leaves no file behind and puts the file name and the system's
// reason in `error`.
bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error);

// What the outputters' write() does: the same, with the reason in `error` when given, on
// stderr otherwise.
bool writeReport(const std::string& filename, const std::string& content, TestMessage* error);

}  // namespace reporters
}  // namespace robottestingframework
