// Windows: the console screen buffer's window behind the stream's handle.
#include "platform/terminal_width.h"

#include <io.h>
#include <windows.h>

namespace robottestingframework {
namespace platform {

std::size_t terminalWidth(std::FILE* stream, std::size_t fallback) {
    HANDLE handle = reinterpret_cast<HANDLE>(::_get_osfhandle(::_fileno(stream)));
    CONSOLE_SCREEN_BUFFER_INFO info{};
    if (handle != INVALID_HANDLE_VALUE && ::GetConsoleScreenBufferInfo(handle, &info)) {
        const long columns = static_cast<long>(info.srWindow.Right) - info.srWindow.Left + 1;
        if (columns > 0) {
            return static_cast<std::size_t>(columns);
        }
    }
    return fallback;
}

}  // namespace platform
}  // namespace robottestingframework
