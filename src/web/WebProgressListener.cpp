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

void WebProgressListener::addReport(const Test* test, TestMessage msg) {
    RTF_TO_PAGE(addReport(test, msg));
}
void WebProgressListener::addError(const Test* test, TestMessage msg) {
    RTF_TO_PAGE(addError(test, msg));
}
void WebProgressListener::addFailure(const Test* test, TestMessage msg) {
    RTF_TO_PAGE(addFailure(test, msg));
}
void WebProgressListener::startTest(const Test* test) {
    RTF_TO_PAGE(startTest(test));
}
void WebProgressListener::endTest(const Test* test) {
    RTF_TO_PAGE(endTest(test));
}
void WebProgressListener::renameTest(const Test* test, const std::string& name) {
    RTF_TO_PAGE(renameTest(test, name));
}
void WebProgressListener::startTestSuite(const TestSuite* suite) {
    RTF_TO_PAGE(startTestSuite(suite));
}
void WebProgressListener::endTestSuite(const TestSuite* suite) {
    RTF_TO_PAGE(endTestSuite(suite));
}
void WebProgressListener::startTestSuite(const Test* suite) {
    RTF_TO_PAGE(startTestSuite(suite));
}
void WebProgressListener::endTestSuite(const Test* suite) {
    RTF_TO_PAGE(endTestSuite(suite));
}
void WebProgressListener::startTestRunner() {
    RTF_TO_PAGE(startTestRunner());
}
void WebProgressListener::endTestRunner() {
    RTF_TO_PAGE(endTestRunner());
}
void WebProgressListener::addCheck(const Test* test, TestMessage msg, bool passed) {
    RTF_TO_PAGE(addCheck(test, msg, passed));
}
void WebProgressListener::addSkipped(const Test* test, TestMessage reason) {
    RTF_TO_PAGE(addSkipped(test, reason));
}
void WebProgressListener::addCrash(const Test* test, TestMessage msg) {
    RTF_TO_PAGE(addCrash(test, msg));
}
void WebProgressListener::addTimeout(const Test* test, TestMessage msg) {
    RTF_TO_PAGE(addTimeout(test, msg));
}
void WebProgressListener::addInterrupted(const Test* test, TestMessage msg) {
    RTF_TO_PAGE(addInterrupted(test, msg));
}
void WebProgressListener::addOutput(const Test* test, const std::string& text) {
    RTF_TO_PAGE(addOutput(test, text));
}
void WebProgressListener::retryTest(const Test* test, TestMessage msg) {
    RTF_TO_PAGE(retryTest(test, msg));
}
void WebProgressListener::startRepetition(const Test* test, unsigned int index,
                                          unsigned int count) {
    RTF_TO_PAGE(startRepetition(test, index, count));
}

void WebProgressListener::addEvent(const Test* test, const ResultEvent& event) {
    RTF_TO_PAGE(addEvent(test, event));
}
void WebProgressListener::onEvent(const RunEvent& event) {
    RTF_TO_PAGE(onEvent(event));
}

#undef RTF_TO_PAGE

}  // namespace robottestingframework
