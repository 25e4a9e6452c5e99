#include "platform/file_kind.h"

namespace robottestingframework {
namespace platform {

const char* fileKindText(std::filesystem::file_type type) {
    using std::filesystem::file_type;
    switch (type) {
        case file_type::directory:
            return "a folder";
        case file_type::fifo:
            return "a FIFO (named pipe)";
        case file_type::character:
            return "a character device";
        case file_type::block:
            return "a block device";
        case file_type::socket:
            return "a socket";
        case file_type::regular:
            return "a regular file";
        default:
            return "not a regular file";
    }
}

}  // namespace platform
}  // namespace robottestingframework
