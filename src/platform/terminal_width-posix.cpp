// POSIX (Linux and macOS alike): the TIOCGWINSZ request on the stream's descriptor.
#include "platform/terminal_width.h"

#include <sys/ioctl.h>
#include <unistd.h>

namespace robottestingframework {
namespace platform {

std::size_t terminalWidth(std::FILE* stream, std::size_t fallback) {
    struct winsize size {};
    if (::ioctl(::fileno(stream), TIOCGWINSZ, &size) == 0 && size.ws_col > 0) {
        return size.ws_col;
    }
    return fallback;
}

}  // namespace platform
}  // namespace robottestingframework
