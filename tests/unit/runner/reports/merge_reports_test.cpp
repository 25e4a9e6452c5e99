// Shards' reports merged into one (merge_reports.h).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <pugixml.hpp>

#include "build_paths.h"
#include "runner/reports/merge_reports.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

// A JUnit report of shard `index` of `count` holding one suite at `place`.
std::string shardReport(int index, int count, int place, const std::string& suite,
                        const std::string& tests, bool rerun = false,
                        const std::string& plan = "") {
    return std::string("<testsuites name=\"RobotTestingFramework\" tests=\"9\">\n<properties>") +
           "<property name=\"rtf.shard.index\" value=\"" + std::to_string(index) + "\"/>" +
           "<property name=\"rtf.shard.count\" value=\"" + std::to_string(count) + "\"/>" +
           (plan.empty() ? "" : "<property name=\"rtf.shard.plan\" value=\"" + plan + "\"/>") +
           (rerun ? "<property name=\"rtf.rerun\" value=\"true\"/>" : "") + "</properties>\n" +
           "<testsuite name=\"" + suite + "\" tests=\"9\" time=\"1.000\" id=\"" +
           std::to_string(place) + "\">\n" + tests + "</testsuite>\n</testsuites>\n";
}

std::string testCase(const std::string& name, const std::string& status) {
    return "<testcase name=\"" + name + "\" classname=\"x\" time=\"0.1\" status=\"" + status +
           "\"/>\n";
}

class MergeReports : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) /
               ("merge_reports_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        const std::string path = (dir_ / name).string();
        std::ofstream(path) << text;
        return path;
    }
    std::string errorOf(const MergeRequest& request) {
        try {
            mergeReports(request);
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        return "(no error)";
    }

    fs::path dir_;
};

}  // namespace

TEST_F(MergeReports, OrdersSuitesByTheirPlaceAndCountsAgain) {
    const auto a = write("a.xml", shardReport(0, 2, 1, "second", testCase("t", "failed")));
    const auto b = write("b.xml", shardReport(1, 2, 0, "first", testCase("t", "passed")));
    pugi::xml_document merged;
    ASSERT_TRUE(merged.load_string(mergeReports({"junit", "out.xml", {a, b}, 2}).c_str()));
    const pugi::xml_node root = merged.document_element();
    EXPECT_FALSE(root.child("properties"));
    EXPECT_STREQ(root.first_child().attribute("name").value(), "first");
    EXPECT_STREQ(root.last_child().attribute("name").value(), "second");
    EXPECT_STREQ(root.attribute("tests").value(), "2");
    EXPECT_STREQ(root.attribute("failures").value(), "1");
    EXPECT_STREQ(root.last_child().attribute("tests").value(), "1");
}

TEST_F(MergeReports, ARerunReplacesTheTestsItRanAgain) {
    const auto first = write(
        "first.xml", shardReport(0, 1, 0, "s", testCase("t", "failed") + testCase("u", "passed")));
    const auto again = write("again.xml", shardReport(0, 1, 0, "s", testCase("t", "passed"), true));
    pugi::xml_document merged;
    ASSERT_TRUE(merged.load_string(mergeReports({"junit", "out.xml", {again, first}, 1}).c_str()));
    const pugi::xml_node suite = merged.document_element().child("testsuite");
    EXPECT_STREQ(suite.first_child().attribute("status").value(), "passed");
    EXPECT_STREQ(suite.attribute("tests").value(), "2");
    EXPECT_STREQ(suite.attribute("failures").value(), "0");
}

TEST_F(MergeReports, ExpectShardsChecksEveryShardOnce) {
    const auto zero = write("0.xml", shardReport(0, 3, 0, "a", testCase("t", "passed")));
    const auto one = write("1.xml", shardReport(1, 3, 1, "b", testCase("t", "passed")));
    const auto oneAgain = write("1b.xml", shardReport(1, 3, 2, "c", testCase("t", "passed")));
    const auto ofTwo = write("2.xml", shardReport(1, 2, 2, "c", testCase("t", "passed")));
    EXPECT_EQ(errorOf({"junit", "out.xml", {zero, one}, 3}),
              "--merge --expect-shards 3: no report of shard 2");
    EXPECT_EQ(errorOf({"junit", "out.xml", {zero, one, oneAgain}, 3}),
              "--merge " + one + " and " + oneAgain + " are both shard 1 of 3");
    EXPECT_EQ(errorOf({"junit", "out.xml", {zero, ofTwo}, 3}),
              "--merge " + ofTwo + ": shard 1 of 2, expected 3 shards (--expect-shards 3)");
}

TEST_F(MergeReports, ASuiteInTwoReportsIsAnError) {
    const auto a = write("a.xml", shardReport(0, 2, 0, "s", testCase("t", "passed")));
    const auto b = write("b.xml", shardReport(1, 2, 0, "s", testCase("t", "passed")));
    EXPECT_NE(errorOf({"junit", "out.xml", {a, b}, 0}).find("both hold suite 's'"),
              std::string::npos);
}

TEST_F(MergeReports, AReportOfTheOtherFormatIsAnError) {
    const auto a = write("a.xml", shardReport(0, 1, 0, "s", testCase("t", "passed")));
    EXPECT_NE(errorOf({"json", "out.json", {a}, 0}).find(a + ": a JUnit report; expected JSON"),
              std::string::npos);
}

TEST_F(MergeReports, ReportsOfNowKeepTheirStatesAndLoseTheShardProperties) {
    // As the runner writes them now: the shard on the suite, the states in the elements.
    const auto suite = [](int index, const char* tests, bool rerun) {
        return std::string(
                   "<testsuites name=\"RobotTestingFramework\">\n<testsuite name=\"s\" "
                   "tests=\"2\" failures=\"0\" errors=\"0\" skipped=\"0\" time=\"1.000\" "
                   "id=\"0\">\n<properties><property name=\"rtf.shard.index\" value=\"") +
               std::to_string(index) + "\"/><property name=\"rtf.shard.count\" value=\"1\"/>" +
               (rerun ? "<property name=\"rtf.rerun\" value=\"true\"/>" : "") + tests +
               "</testsuite>\n</testsuites>\n";
    };
    const auto first =
        write("first.xml",
              suite(0,
                    "<property name=\"rtf.state.1.1\" value=\"timed out\"/></properties>\n"
                    "<testcase name=\"t\" classname=\"s\" time=\"0.1\"><failure type=\"timeout\"/>"
                    "</testcase>\n<testcase name=\"u\" classname=\"s\" time=\"0.1\"/>\n",
                    false));
    const auto again =
        write("again.xml", suite(0,
                                 "<property name=\"rtf.state.1.1\" value=\"flaky\"/></properties>\n"
                                 "<testcase name=\"t\" classname=\"s\" time=\"0.1\"><flakyFailure "
                                 "type=\"timed out\"><stackTrace>x</stackTrace></flakyFailure>"
                                 "</testcase>\n",
                                 true));
    pugi::xml_document merged;
    ASSERT_TRUE(merged.load_string(mergeReports({"junit", "out.xml", {first, again}, 1}).c_str()));
    const pugi::xml_node root = merged.document_element();
    EXPECT_STREQ(root.attribute("tests").value(), "2");
    EXPECT_STREQ(root.attribute("failures").value(), "0");
    // The timeout was run again and passed: only "flaky" names it now, no shard is named.
    const pugi::xml_node properties = root.child("testsuite").child("properties");
    std::string names;
    for (const pugi::xml_node property : properties.children("property")) {
        names += std::string(property.attribute("name").value()) + "=" +
                 property.attribute("value").value() + " ";
    }
    EXPECT_EQ(names, "rtf.state.1.1=flaky ");
}

TEST_F(MergeReports, AShardOfAnotherRunIsAnErrorNamingIt) {
    const auto zero = write(
        "A0.xml", shardReport(0, 3, 0, "a", testCase("t", "passed"), false, "00000000000000aa"));
    const auto one = write(
        "B1.xml", shardReport(1, 3, 1, "x", testCase("t", "passed"), false, "00000000000000bb"));
    const auto two = write(
        "A2.xml", shardReport(2, 3, 2, "c", testCase("t", "passed"), false, "00000000000000aa"));
    const auto old = write("old1.xml", shardReport(1, 3, 1, "b", testCase("t", "passed")));
    // Whatever the order: the plan most reports say is the run's.
    for (const auto& reports :
         {std::vector<std::string>{zero, one, two}, std::vector<std::string>{one, zero, two}}) {
        const std::string error = errorOf({"junit", "out.xml", reports, 3});
        EXPECT_EQ(error.rfind("--merge " + one +
                                  ": a report of another run (its plan is "
                                  "00000000000000bb; the shards of 2 other report(s) are of plan "
                                  "00000000000000aa)",
                              0),
                  0U)
            << error;
    }
    // A report that says no plan, beside reports that say one.
    EXPECT_EQ(errorOf({"junit", "out.xml", {zero, old, two}, 3})
                  .rfind("--merge " + old + ": a report of another run (it says no plan", 0),
              0U);
    // The shards of one run merge.
    const auto oneOfA = write(
        "A1.xml", shardReport(1, 3, 1, "b", testCase("t", "passed"), false, "00000000000000aa"));
    pugi::xml_document merged;
    ASSERT_TRUE(
        merged.load_string(mergeReports({"junit", "out.xml", {zero, oneOfA, two}, 3}).c_str()));
    EXPECT_EQ(std::string(merged.document_element().attribute("tests").value()), "3");
    for (const pugi::xml_node suite : merged.document_element().children("testsuite")) {
        for (const pugi::xml_node property : suite.child("properties").children("property")) {
            EXPECT_STRNE(property.attribute("name").value(), "rtf.shard.plan");
        }
    }
}
