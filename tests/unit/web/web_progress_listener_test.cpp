// WebProgressListener used directly by a program, as RTF 2.x users do: each listener serves
// its own page; what /status, /snapshot and /update say follows the run.
#include <string>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>
#include <robottestingframework/WebProgressListener.h>

#include "core_test_helpers.h"

using namespace robottestingframework;
using rtf_test::LambdaTest;

namespace {

std::string get(const WebProgressListener& web, const std::string& path, int* status = nullptr) {
    httplib::Client client("127.0.0.1", static_cast<int>(web.port()));
    client.set_connection_timeout(5);
    client.set_read_timeout(5);
    auto response = client.Get(path.c_str());
    if (!response) {
        return "<no answer>";
    }
    if (status != nullptr) {
        *status = response->status;
    }
    return response->body;
}

nlohmann::json getJson(const WebProgressListener& web, const std::string& path) {
    return nlohmann::json::parse(get(web, path));
}

}  // namespace

TEST(WebProgressListener, TwoListenersOnTwoPortsServeTheSameRun) {
    WebProgressListener first(0);
    WebProgressListener second(0);
    ASSERT_TRUE(first.isListening()) << first.error();
    ASSERT_TRUE(second.isListening()) << second.error();
    EXPECT_NE(first.port(), second.port());
    EXPECT_EQ(first.url(), "http://127.0.0.1:" + std::to_string(first.port()) + "/");

    LambdaTest passing("passing");
    LambdaTest failing("failing \"quoted\" </script>",
                       [] { ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(false, "<b>broken</b>"); });
    LambdaTest later("later");
    TestSuite suite("arm <suite>");
    suite.addTest(&passing);
    suite.addTest(&failing);
    suite.addTest(&later);
    // While `failing` runs, the second page sees it running and `later` not run yet.
    nlohmann::json duringRun;
    failing.onSetup = [&] {
        duringRun = getJson(second, "/status");
        return true;
    };

    TestResult result;
    result.addListener(&first);
    result.addListener(&second);
    result.startTestRunner();
    suite.run(result);
    result.endTestRunner();

    EXPECT_EQ(duringRun["name"], "arm <suite>");
    EXPECT_EQ(duringRun["testStatus"], nlohmann::json::parse("[3, 1, 0]"));
    // Both pages are served after the run, until the listeners are gone.
    for (const WebProgressListener* web : {&first, &second}) {
        nlohmann::json status = getJson(*web, "/status");
        EXPECT_EQ(status["name"], "arm <suite>");
        EXPECT_EQ(status["testStatus"], nlohmann::json::parse("[3, 2, 3]"));
        nlohmann::json snapshot = getJson(*web, "/snapshot");
        EXPECT_EQ(snapshot["run"]["state"], "finished");
        EXPECT_EQ(snapshot["run"]["failed"], 1);
        EXPECT_EQ(snapshot["suites"][0]["tests"][1]["name"], "failing \"quoted\" </script>");
        EXPECT_EQ(snapshot["suites"][0]["tests"][1]["state"], "failed");
        EXPECT_EQ(snapshot["suites"][0]["tests"][1]["messages"][0]["kind"], "failure");
    }
    std::string log = get(first, "/update");
    EXPECT_NE(log.find("&lt;b&gt;broken&lt;/b&gt;"), std::string::npos) << log;
    EXPECT_EQ(log.find("<b>"), std::string::npos) << log;
}

TEST(WebProgressListener, APortInUseIsReportedNotServed) {
    WebProgressListener first(0);
    ASSERT_TRUE(first.isListening());
    ::testing::internal::CaptureStderr();
    WebProgressListener second(first.port());
    std::string said = ::testing::internal::GetCapturedStderr();
    EXPECT_FALSE(second.isListening());
    // RTF 2.x's constructor has no way to return the failure: it is said on stderr.
    EXPECT_NE(said.find("WebProgressListener: cannot listen on 127.0.0.1:" +
                        std::to_string(first.port())),
              std::string::npos)
        << said;
    EXPECT_EQ(second.port(), 0u);
    EXPECT_NE(second.error().find(std::to_string(first.port())), std::string::npos)
        << second.error();
}

TEST(WebProgressListener, RefusesOtherMethodsAndForeignHosts) {
    WebProgressListener web(0);
    ASSERT_TRUE(web.isListening());
    httplib::Client client("127.0.0.1", static_cast<int>(web.port()));
    auto posted = client.Post("/status", "x", "text/plain");
    ASSERT_TRUE(posted);
    EXPECT_EQ(posted->status, 405);
    auto foreign = client.Get("/status", {{"Host", "attacker.example:80"}});
    ASSERT_TRUE(foreign);
    EXPECT_EQ(foreign->status, 403);
    auto page = client.Get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_TRUE(page->has_header("Content-Security-Policy"));
    EXPECT_FALSE(page->has_header("Access-Control-Allow-Origin"));
}
