// The listening socket's options: the port is the server's alone, so a second server asked for
// the same port is told it is in use instead of sharing it or taking it over.
#pragma once

#include <cstdint>

namespace robottestingframework {
namespace web {

// `socket` is the platform's socket (a descriptor, or a Winsock SOCKET), before bind().
void claimPortAlone(std::uintptr_t socket);

}  // namespace web
}  // namespace robottestingframework
