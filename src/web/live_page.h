// What RTF's WebProgressListener asks of the live page RTF_web serves. The page (cpp-httplib,
// and OpenSSL with it) is in a library of its own that WebProgressListener loads on first use:
// a program that links RTF only, like the runner, maps it only when it shows a page.
#pragma once

#include <string>
#include <vector>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestSuite.h>

namespace robottestingframework {
namespace web {

// Hears a run's events and serves them until destroyed.
class LivePage : public TestListener {
public:
    // False when it could not listen (the port is in use, ...); error() says why.
    virtual bool isListening() const = 0;
    virtual std::string error() const = 0;
    // The port served (the one picked when 0 was asked).
    virtual unsigned int port() const = 0;
    // The recent runs of the test "SUITE/TEST" (--history), as JSON the page draws beside it:
    // {"states":[...],"durations":[...],"flakyRate":R}. Given before the run starts.
    virtual void setTestHistory(const std::string& testId, const std::string& json) = 0;
    // The run's suites and their tests, shown from the start (after setTestHistory).
    virtual void setPlan(const std::vector<const TestSuite*>& suites) = 0;
};

// RTF_web's factory, found by this name: a page on host:port (0 picks a free one), never null.
using OpenLivePage = LivePage* (*)(const char* host, unsigned int port, bool verbose);
constexpr const char* openLivePageSymbol = "robottestingframework_web_open_live_page";

}  // namespace web
}  // namespace robottestingframework
