// A live web page of a run: add the listener to a TestResult and open its url() in a browser.
// The page shows every suite and test as it happens (state, duration, messages) and updates
// itself; it is served from construction until destruction, so also after run() returns.
//
// Part of RobotTestingFramework::RTF, as in RTF 2.x. The server is in the RTF_web library
// (cpp-httplib), which the first listener loads from beside the RTF library: programs that
// never make a listener do not load it. Each listener has its own server: several listeners on
// different ports work side by side.
//
// Endpoints: "/" (the page), "/snapshot" (the whole run as JSON), "/events" (Server-Sent Events,
// replayed from Last-Event-ID or ?since=N), and RTF 2.x's "/status" and "/update".
// Only GET is answered, and only when the Host header names the bound address or localhost.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestSuite.h>

namespace robottestingframework {

class WebProgressListener : public TestListener {
public:
    // Listens on 127.0.0.1:port; port 0 picks a free one (see port()). `verbose` also shows
    // what the tests print. When it cannot listen, it says so on stderr (and isListening()).
    WebProgressListener(unsigned int port = 8080, bool verbose = false);
    // Listens on `host` ("127.0.0.1", "::1", "0.0.0.0", ...) instead; a failure to listen is
    // only told by isListening() and error(), for the caller to report.
    WebProgressListener(const std::string& host, unsigned int port, bool verbose = false);
    ~WebProgressListener() override;

    WebProgressListener(const WebProgressListener&) = delete;
    WebProgressListener& operator=(const WebProgressListener&) = delete;

    // False when the server could not start (the port is in use, RTF_web cannot be loaded,
    // ...); error() says why.
    bool isListening() const;
    std::string error() const;
    // The port served (the one picked when 0 was asked), 0 when not listening.
    unsigned int port() const;
    // "http://127.0.0.1:8080/".
    std::string url() const;
    // The recent runs of the test "SUITE/TEST", drawn beside it on the page: JSON
    // {"states":[...],"durations":[...],"flakyRate":R} (the runner's --history). Give it
    // before the test's suite starts.
    void setTestHistory(const std::string& testId, const std::string& json);
    // The suites the run will run, in order: each one and its tests are on the page from the
    // start, also those that start later (side by side with -j N). Give it after
    // setTestHistory and before the run starts; without it, suites show as they start.
    void setPlan(const std::vector<const TestSuite*>& suites);

    // Every event of a run reaches the page as the record, whatever its kind: the one
    // forwarder (the named handlers of TestListener stay the adapter of RTF 2.x's listeners).
    void onEvent(const RunEvent& event) override;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace robottestingframework
