#include <robottestingframework/WebProgressListener.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include <robottestingframework/TestSuite.h>

#include "run_view.h"
#include "web_server.h"

namespace robottestingframework {

// The view is filled by the run's events and read by the server; tests are found by the ids
// the events carry.
struct WebProgressListener::State {
    State(const std::string& host, unsigned int port, bool verbose)
        : view(verbose), server(view), host(host) {
        listening = server.start(host, port, error);
    }
    ~State() {
        view.close();  // ends the event streams first, so stop() does not wait for them
        server.stop();
    }
    void message(const Test* test, const char* kind, const TestMessage& msg, TestStatus status) {
        view.addMessage(idOf(test), kind, msg, status);
    }
    static std::uint64_t idOf(const Test* test) { return test != nullptr ? test->getId() : 0; }

    web::RunView view;
    web::WebServer server;
    std::string host;
    std::string error;
    bool listening = false;
};

WebProgressListener::WebProgressListener(unsigned int port, bool verbose)
    : WebProgressListener("127.0.0.1", port, verbose) {
    // RTF 2.x's programs do not ask isListening(): say it rather than serve nothing silently.
    if (!state_->listening) {
        std::fprintf(stderr, "WebProgressListener: %s\n", state_->error.c_str());
    }
}

WebProgressListener::WebProgressListener(const std::string& host, unsigned int port, bool verbose)
    : state_(new State(host, port, verbose)) {}

WebProgressListener::~WebProgressListener() = default;

bool WebProgressListener::isListening() const {
    return state_->listening;
}

std::string WebProgressListener::error() const {
    return state_->error;
}

unsigned int WebProgressListener::port() const {
    return state_->listening ? state_->server.port() : 0;
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

void WebProgressListener::addReport(const Test* test, TestMessage msg) {
    state_->message(test, "report", msg, TestStatus::Passed);
}

void WebProgressListener::addError(const Test* test, TestMessage msg) {
    state_->message(test, "error", msg, TestStatus::Error);
}

void WebProgressListener::addFailure(const Test* test, TestMessage msg) {
    state_->message(test, "failure", msg, TestStatus::Failed);
}

void WebProgressListener::addCheck(const Test* test, TestMessage msg, bool passed) {
    // Passing checks are many and say little; a failed one is shown with its failure.
    if (!passed) {
        state_->message(test, "check failed", msg, TestStatus::Passed);
    }
}

void WebProgressListener::addSkipped(const Test* test, TestMessage reason) {
    state_->message(test, "skipped", reason, TestStatus::Skipped);
}

void WebProgressListener::addCrash(const Test* test, TestMessage msg) {
    state_->message(test, "crash", msg, TestStatus::Crashed);
}

void WebProgressListener::addTimeout(const Test* test, TestMessage msg) {
    state_->message(test, "timeout", msg, TestStatus::TimedOut);
}

void WebProgressListener::addInterrupted(const Test* test, TestMessage msg) {
    state_->message(test, "interrupted", msg, TestStatus::Interrupted);
}

void WebProgressListener::addOutput(const Test* test, const std::string& text) {
    state_->view.addOutput(State::idOf(test), text);
}

void WebProgressListener::retryTest(const Test* test, TestMessage /*msg*/) {
    state_->view.retryTest(State::idOf(test));
}

void WebProgressListener::startRepetition(const Test* test, unsigned int index,
                                          unsigned int count) {
    state_->view.startRepetition(State::idOf(test), index, count);
}

void WebProgressListener::startTest(const Test* test) {
    state_->view.startTest(State::idOf(test), test != nullptr ? test->getName() : std::string());
}

void WebProgressListener::endTest(const Test* test) {
    state_->view.endTest(State::idOf(test));
}

void WebProgressListener::renameTest(const Test* test, const std::string& name) {
    state_->view.renameTest(State::idOf(test), name);
}

void WebProgressListener::startTestSuite(const TestSuite* suite) {
    std::vector<web::RunView::Planned> tests;
    if (suite != nullptr) {
        for (const Test* test : suite->tests()) {
            tests.push_back({test->getId(), test->getName()});
        }
    }
    state_->view.startSuite(suite != nullptr ? suite->getName() : std::string(), tests);
}

void WebProgressListener::endTestSuite(const TestSuite* suite) {
    endTestSuite(static_cast<const Test*>(suite));
}

void WebProgressListener::startTestSuite(const Test* suite) {
    // A suite known only as a Test: its tests are learnt as they start.
    state_->view.startSuite(suite != nullptr ? suite->getName() : std::string(), {});
}

void WebProgressListener::endTestSuite(const Test* /*suite*/) {
    state_->view.endSuite();
}

void WebProgressListener::startTestRunner() {
    state_->view.startRun();
}

void WebProgressListener::endTestRunner() {
    state_->view.endRun();
}

}  // namespace robottestingframework
