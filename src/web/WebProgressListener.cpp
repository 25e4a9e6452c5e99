// Part of RTF, as in RTF 2.x: linking RTF is enough to show a run's live page. The page itself
// is RTF_web's (live_page.h), loaded on the first construction, so that the programs linking
// RTF that never show one (the runner without --web-reporter) do not load its libraries.
#include <robottestingframework/WebProgressListener.h>

#include <cstdio>

#include "web/live_page.h"
#include "web/live_page_library.h"

namespace robottestingframework {

struct WebProgressListener::State {
    std::unique_ptr<web::LivePage> page;  // null when RTF_web could not be loaded
    std::string host;
    std::string loadError;
};

WebProgressListener::WebProgressListener(unsigned int port, bool verbose)
    : WebProgressListener("127.0.0.1", port, verbose) {
    // RTF 2.x's programs do not ask isListening(): say it rather than serve nothing silently.
    if (!isListening()) {
        std::fprintf(stderr, "WebProgressListener: %s\n", error().c_str());
    }
}

WebProgressListener::WebProgressListener(const std::string& host, unsigned int port, bool verbose)
    : state_(new State) {
    state_->host = host;
    if (web::OpenLivePage open = web::loadLivePageLibrary(state_->loadError)) {
        state_->page.reset(open(host.c_str(), port, verbose));
    }
}

WebProgressListener::~WebProgressListener() = default;

void WebProgressListener::setTestHistory(const std::string& testId, const std::string& json) {
    if (state_->page) {
        state_->page->setTestHistory(testId, json);
    }
}

void WebProgressListener::setPlan(const std::vector<const TestSuite*>& suites) {
    if (state_->page) {
        state_->page->setPlan(suites);
    }
}

bool WebProgressListener::isListening() const {
    return state_->page != nullptr && state_->page->isListening();
}

std::string WebProgressListener::error() const {
    return state_->page != nullptr ? state_->page->error() : state_->loadError;
}

unsigned int WebProgressListener::port() const {
    return isListening() ? state_->page->port() : 0;
}

std::string WebProgressListener::url() const {
    const std::string& host = state_->host;
    std::string shown = host;
    if (host == "0.0.0.0" || host == "::") {
        shown = "127.0.0.1";  // every address: this machine's is one of them
    } else if (host.find(':') != std::string::npos) {
        shown = "[" + host + "]";
    }
    return "http://" + shown + ":" + std::to_string(port()) + "/";
}

// Every event goes to the page, when there is one.
#define RTF_TO_PAGE(call)              \
    do {                               \
        if (state_->page != nullptr) { \
            state_->page->call;        \
        }                              \
    } while (false)

void WebProgressListener::onEvent(const RunEvent& event) {
    RTF_TO_PAGE(onEvent(event));
}

#undef RTF_TO_PAGE

}  // namespace robottestingframework
