// Windows, macOS and the portable POSIX build (Linux built with RTF_PORTABLE_POSIX): no network
// namespaces, so no private network: create() says so, and the run stops before it starts.
#include "platform/private_network.h"

namespace robottestingframework {
namespace platform {

std::unique_ptr<PrivateNetwork> PrivateNetwork::create(std::string& error) {
    error =
        "a private network cannot be made: this build has no network namespaces (Windows, "
        "macOS and the portable POSIX build have none): a private network needs the Linux build";
    return nullptr;
}

std::vector<int> PrivateNetwork::descriptors() const {
    return {};
}

bool joinPrivateNetwork(const std::vector<int>&, std::string& error) {
    error = "no private network in this build";
    return false;
}

ThreadInNetwork::~ThreadInNetwork() = default;

bool ThreadInNetwork::enter(const PrivateNetwork&, std::string& error) {
    error = "no private network in this build";
    return false;
}

}  // namespace platform
}  // namespace robottestingframework
