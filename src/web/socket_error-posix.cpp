#include "web/socket_error.h"

#include <cerrno>
#include <cstring>

namespace robottestingframework {
namespace web {

void clearSocketError() {
    errno = 0;
}

std::string socketError(const std::string& fallback) {
    return errno != 0 ? std::strerror(errno) : fallback;
}

}  // namespace web
}  // namespace robottestingframework
