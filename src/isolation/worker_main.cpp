// robottestingframework-worker: the runner's helper process. Started by the runner as
//   robottestingframework-worker --fork-server FD [--verbose]
// with FD a packet socket to the runner; not meant to be run by hand.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "isolation/fork_server_client.h"
#include "isolation/fork_server_loop.h"

int main(int argc, char** argv) {
    // The loader has bound every symbol already (see ForkServer::start); the tests' own
    // programs start as the user's environment says.
    if (std::getenv(robottestingframework::isolation::kBindNowMark) != nullptr) {
        ::unsetenv("LD_BIND_NOW");
        ::unsetenv(robottestingframework::isolation::kBindNowMark);
    }
    bool verbose = argc == 4 && std::strcmp(argv[3], "--verbose") == 0;
    if ((argc == 3 || verbose) && std::strcmp(argv[1], "--fork-server") == 0) {
        char* end = nullptr;
        long fd = std::strtol(argv[2], &end, 10);
        if (end != argv[2] && *end == '\0' && fd >= 0) {
            return robottestingframework::isolation::serveForkRequests(static_cast<int>(fd),
                                                                       verbose);
        }
    }
    std::fprintf(stderr,
                 "%s: the test runner's worker; it is started by robottestingframework-testrunner "
                 "(usage: %s --fork-server FD [--verbose])\n",
                 argv[0], argv[0]);
    return 2;
}
