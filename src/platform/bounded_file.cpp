#include "platform/bounded_file.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "platform/file_kind.h"

namespace robottestingframework {
namespace platform {

namespace {

// "16 MiB", "512 KiB", "100 bytes".
std::string sizeText(std::size_t bytes) {
    if (bytes >= 1024 * 1024 && bytes % (1024 * 1024) == 0) {
        return std::to_string(bytes / (1024 * 1024)) + " MiB";
    }
    if (bytes >= 1024 && bytes % 1024 == 0) {
        return std::to_string(bytes / 1024) + " KiB";
    }
    return std::to_string(bytes) + " bytes";
}

}  // namespace

bool readBoundedFile(const std::string& path, const std::string& what, std::size_t limit,
                     Pipes pipes, std::string& content, std::string& error) {
    // std::filesystem rather than stat(): the same answers on POSIX and Windows.
    using std::filesystem::file_type;
    std::error_code failed;
    const file_type type = std::filesystem::status(path, failed).type();
    if (failed || type == file_type::not_found) {
        const std::string reason = failed ? failed.message() : std::string(std::strerror(ENOENT));
        error = path + ": cannot read the " + what + " (" + reason + ")";
        return false;
    }
    if (type == file_type::directory) {
        error = path + ": is a folder, not a " + what;
        return false;
    }
    const bool pipe = type == file_type::fifo && pipes == Pipes::Read;
    if (type != file_type::regular && !pipe) {
        error = path + ": is " + std::string(fileKindText(type)) + ", not a " + what + " (a " +
                what + " is a regular file" + (pipes == Pipes::Read ? " or a pipe)" : ")");
        return false;
    }
    const std::string tooLarge =
        path + ": the " + what + " is larger than " + sizeText(limit) + ", the limit of a " + what;
    const std::uintmax_t size = pipe ? 0 : std::filesystem::file_size(path, failed);
    if (!pipe && !failed && size > limit) {
        error = tooLarge;
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path + ": cannot read the " + what + " (" + std::strerror(errno) + ")";
        return false;
    }
    // Up to one byte past the limit: a file can grow after its size was read, a pipe has none.
    content.clear();
    content.reserve(pipe || failed ? 0 : static_cast<std::size_t>(size));
    char chunk[65536];
    while (in && content.size() <= limit) {
        in.read(chunk, sizeof chunk);
        content.append(chunk, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) {
        error = path + ": cannot read the " + what;
        return false;
    }
    if (content.size() > limit) {
        content.clear();
        content.shrink_to_fit();
        error = tooLarge;
        return false;
    }
    return true;
}

}  // namespace platform
}  // namespace robottestingframework
