#include "runner/cli/private_networks.h"

#include <cstdio>

#include "platform/clock.h"
#include "platform/private_network.h"
#include "runner/cli/program_name.h"

namespace robottestingframework {
namespace runner {

bool preparePrivateNetworks(const Options& options, std::vector<SuiteSpec>& suites,
                            std::string& error, std::string& note) {
    const SuiteSpec* asking = nullptr;
    for (auto& suite : suites) {
        if (options.privateNetworks) {
            suite.network = SuiteSpec::Network::Private;
        }
        if (asking == nullptr && suite.network == SuiteSpec::Network::Private) {
            asking = &suite;
        }
    }
    if (asking == nullptr) {
        return true;
    }
    const std::string who =
        options.privateNetworks
            ? std::string("--network private")
            : "suite " + asking->name + " (" + asking->where.toString() + ", network=\"private\")";
    const double start = platform::monotonicSeconds();
    std::string why;
    const auto probe = platform::PrivateNetwork::create(why);
    const double seconds = platform::monotonicSeconds() - start;
    if (!probe) {
        error = who + ": " + why;
        return false;
    }
    if (options.isolation == Isolation::None && !probe->joinableByThread()) {
        error = who +
                " with --isolation none: the runner's thread must join each suite's "
                "network, which only root can (as another user the network is made in a "
                "user namespace, which a process with threads cannot join); run with "
                "--isolation process (the default), or as root";
        return false;
    }
    char cost[64];
    std::snprintf(cost, sizeof cost, "%.2f ms", seconds * 1000);
    note = std::string("a private network is made in ") + cost +
           (probe->joinableByThread() ? " (a network namespace)"
                                      : " (a user and a network namespace)");
    return true;
}

bool setUpPrivateNetworks(const Options& options, std::vector<SuiteSpec>& suites) {
    std::string error, cost;
    if (!preparePrivateNetworks(options, suites, error, cost)) {
        std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
        return false;
    }
    if (options.verbose && !cost.empty()) {
        std::printf("%s: %s\n", programName, cost.c_str());
    }
    return true;
}

}  // namespace runner
}  // namespace robottestingframework
