#include "web/socket_error.h"

#include <winsock2.h>
// After winsock2.h.
#include <windows.h>

#include "platform/system_error.h"

namespace robottestingframework {
namespace web {

void clearSocketError() {
    ::WSASetLastError(0);
}

std::string socketError(const std::string& fallback) {
    const int code = ::WSAGetLastError();
    if (code == 0) {
        return fallback;
    }
    const std::string number = "(Winsock error " + std::to_string(code) + ")";
    // Windows' own words for it ("Only one usage of each socket address ... is normally
    // permitted") do not say "in use".
    if (code == WSAEADDRINUSE) {
        return "the port is in use by another program " + number;
    }
    return platform::systemErrorText(static_cast<unsigned long>(code)) + " " + number;
}

}  // namespace web
}  // namespace robottestingframework
