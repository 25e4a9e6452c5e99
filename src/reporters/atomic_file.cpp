#include "reporters/atomic_file.h"

#include <cstdio>

// What every platform shares; writeFileAtomically is in atomic_file-<platform>.cpp.
namespace robottestingframework {
namespace reporters {

bool writeReport(const std::string& filename, const std::string& content, TestMessage* error) {
    std::string why;
    if (writeFileAtomically(filename, content, why)) {
        return true;
    }
    if (error != nullptr) {
        error->setMessage(why);
    } else {
        std::fprintf(stderr, "robottestingframework: %s\n", why.c_str());
    }
    return false;
}

}  // namespace reporters
}  // namespace robottestingframework
