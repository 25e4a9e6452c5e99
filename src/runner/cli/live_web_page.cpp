#include "runner/cli/live_web_page.h"

#include <signal.h>

#include <cstdio>

#include "platform/signal_pipe.h"
#include "runner/cli/program_name.h"

namespace robottestingframework {
namespace runner {

std::unique_ptr<WebProgressListener> startWebPage(const Options& options) {
    if (options.webHost != "127.0.0.1") {
        std::fprintf(stderr,
                     "%s: warning: --web-host %s: the page of the run is served beyond "
                     "this machine's loopback address\n",
                     programName, options.webHost.c_str());
    }
    auto web = std::make_unique<WebProgressListener>(
        options.webHost, static_cast<unsigned int>(options.webPort), options.verbose);
    if (!web->isListening()) {
        std::fprintf(stderr, "%s: --web-port %d: %s\n", programName, options.webPort,
                     web->error().c_str());
        return nullptr;
    }
    std::fprintf(stdout, "%s: live web page at %s\n", programName, web->url().c_str());
    std::fflush(stdout);
    return web;
}

std::vector<const TestSuite*> plannedSuites(RunPlan& plan) {
    std::vector<const TestSuite*> suites;
    for (std::size_t s = 0; s < plan.suiteCount(); ++s) {
        suites.push_back(&plan.suite(s));
    }
    return suites;
}

void lingerOn(const WebProgressListener& web, double seconds) {
    platform::SignalPipe signals({SIGINT, SIGTERM});  // before saying Ctrl-C works
    std::fprintf(stdout, "%s: the final page stays at %s for %g s (Ctrl-C to quit)\n", programName,
                 web.url().c_str(), seconds);
    std::fflush(stdout);
    signals.wait(static_cast<int>(seconds * 1000));
}

}  // namespace runner
}  // namespace robottestingframework
