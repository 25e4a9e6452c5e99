#include "web/exclusive_port.h"

#include <winsock2.h>

namespace robottestingframework {
namespace web {

// Winsock's SO_REUSEADDR would let a second server take the port over; SO_EXCLUSIVEADDRUSE
// makes its bind fail instead (cpp-httplib's default sets SO_REUSEADDR).
void claimPortAlone(std::uintptr_t socket) {
    BOOL yes = TRUE;
    ::setsockopt(static_cast<SOCKET>(socket), SOL_SOCKET, SO_EXCLUSIVEADDRUSE,
                 reinterpret_cast<const char*>(&yes), sizeof(yes));
}

}  // namespace web
}  // namespace robottestingframework
