#include "web/exclusive_port.h"

#include <sys/socket.h>

namespace robottestingframework {
namespace web {

// SO_REUSEADDR only (a restarted run gets its port back at once); cpp-httplib's default adds
// SO_REUSEPORT, with which a second server on the port would share it.
void claimPortAlone(std::uintptr_t socket) {
    int yes = 1;
    ::setsockopt(static_cast<int>(socket), SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
}

}  // namespace web
}  // namespace robottestingframework
