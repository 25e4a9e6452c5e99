#include "atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace robottestingframework {
namespace reporters {

bool writeFileAtomically(const std::string& filename, const std::string& content,
                         std::string& error) {
    const std::string temporary = filename + ".tmp." + std::to_string(::getpid());
    auto fail = [&](const std::string& what, int code) {
        error = "cannot " + what + " " + filename + ": " + std::strerror(code);
        std::remove(temporary.c_str());
        return false;
    };
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr) {
        return fail("write", errno);
    }
    const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
    const int writeErrno = errno;
    if (std::fclose(file) != 0 || !written) {
        return fail("write", written ? errno : writeErrno);
    }
    if (std::rename(temporary.c_str(), filename.c_str()) != 0) {
        return fail("rename a temporary file to", errno);
    }
    return true;
}

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
