#include "reporters/atomic_file.h"

#include <cstdio>

// What every platform shares; AtomicFile itself is in atomic_file-<platform>.cpp.
namespace robottestingframework {
namespace reporters {

bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error) {
    AtomicFile file;
    if (!file.open(filename, error)) {
        return false;
    }
    file.write(content.data(), content.size());
    return file.commit(error);
}

void reportWriteError(const std::string& why, TestMessage* error) {
    if (error != nullptr) {
        error->setMessage(why);
    } else {
        std::fprintf(stderr, "robottestingframework: %s\n", why.c_str());
    }
}

bool writeReport(const std::string& filename, const std::string& content, TestMessage* error) {
    std::string why;
    if (writeFileAtomically(filename, content, why)) {
        return true;
    }
    reportWriteError(why, error);
    return false;
}

}  // namespace reporters
}  // namespace robottestingframework
