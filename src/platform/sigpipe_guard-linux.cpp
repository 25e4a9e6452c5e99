// Linux: every send passes MSG_NOSIGNAL (noSigpipeSendFlags()); there is nothing to guard.
#include "platform/sigpipe_guard.h"

namespace robottestingframework {
namespace platform {

SigpipeGuard::SigpipeGuard() : previous_() {}

SigpipeGuard::~SigpipeGuard() = default;

}  // namespace platform
}  // namespace robottestingframework
