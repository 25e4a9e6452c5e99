// The last socket call's error in the platform's words, for messages such as "cannot listen on
// 127.0.0.1:8080: ...": errno on POSIX; on Windows Winsock's own (WSAGetLastError), which
// errno never holds.
#pragma once

#include <string>

namespace robottestingframework {
namespace web {

// Forgets the last error, before the socket calls whose failure socketError() explains.
void clearSocketError();
// "Address already in use"; on Windows "the port is in use by another program (Winsock error
// 10048)". `fallback` when no call failed with an error.
std::string socketError(const std::string& fallback);

}  // namespace web
}  // namespace robottestingframework
