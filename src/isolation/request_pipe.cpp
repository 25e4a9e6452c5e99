#include "isolation/request_pipe.h"

#include <cstdint>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace isolation {

namespace {

// Reads exactly `size` bytes into `out` (more may not be read: fixture calls follow).
bool readExactly(int fd, std::string& out, std::size_t size) {
    while (out.size() < size) {
        if (platform::readSome(fd, out, size - out.size()) <= 0) {
            return false;
        }
    }
    return true;
}

}  // namespace

std::string frameRequest(const WorkRequest& request) {
    const std::string body = encodeRequest(request);
    std::string framed;
    const auto size = static_cast<std::uint32_t>(body.size());
    for (int shift = 0; shift < 32; shift += 8) {
        framed.push_back(static_cast<char>((size >> shift) & 0xFF));
    }
    return framed + body;
}

bool readRequest(int fd, WorkRequest& request) {
    std::string header;
    if (!readExactly(fd, header, 4)) {
        return false;
    }
    std::uint32_t size = 0;
    for (int i = 3; i >= 0; --i) {
        size = (size << 8) | static_cast<unsigned char>(header[static_cast<std::size_t>(i)]);
    }
    if (size > kMaxRecordSize) {
        return false;
    }
    std::string body;
    return readExactly(fd, body, size) && decodeRequest(body, request);
}

}  // namespace isolation
}  // namespace robottestingframework
