#include "web/socket_error.h"

#include <winsock2.h>
// After winsock2.h.
#include <windows.h>

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
    char buffer[512] = {};
    const DWORD length =
        ::FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr,
                         static_cast<DWORD>(code), 0, buffer, sizeof(buffer), nullptr);
    std::string text(buffer, length);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ' ||
                             text.back() == '.')) {
        text.pop_back();
    }
    return (text.empty() ? std::string("socket error") : text) + " " + number;
}

}  // namespace web
}  // namespace robottestingframework
