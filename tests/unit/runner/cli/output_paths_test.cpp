// Outputs that would replace a folder, an input of the run or another output are refused.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "build_paths.h"
#include "runner/cli/output_paths.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

class OutputPaths : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) /
               ("output_paths_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        std::ofstream(dir_ / "suite.xml") << "<suite/>";
        suite_.where.file = (dir_ / "suite.xml").string();
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string check(std::vector<OutputRequest> outputs) {
        return checkOutputPaths(outputs, {suite_});
    }

    fs::path dir_;
    SuiteSpec suite_;
};

}  // namespace

TEST_F(OutputPaths, NewFilesAndDevicesAreFine) {
    EXPECT_EQ(check({{"junit", (dir_ / "a.xml").string()}, {"text", (dir_ / "b.txt").string()}}),
              "");
    EXPECT_EQ(check({{"junit", "/dev/null"}, {"text", "/dev/null"}}), "");
}

TEST_F(OutputPaths, AFolderIsRefused) {
    const std::string folder = dir_.string();
    EXPECT_EQ(check({{"text", folder}})
                  .rfind("--output text:" + folder + ": " + folder + " is a folder", 0),
              0u);
}

TEST_F(OutputPaths, TheSuiteFileIsRefusedByAnyName) {
    fs::create_symlink(dir_ / "suite.xml", dir_ / "link.xml");
    for (const fs::path& name : {dir_ / "suite.xml", dir_ / "." / "suite.xml", dir_ / "link.xml"}) {
        const std::string problem = check({{"junit", name.string()}});
        EXPECT_NE(problem.find("is the suite file " + suite_.where.file), std::string::npos)
            << name << ": " << problem;
    }
}

TEST_F(OutputPaths, TwoOutputsToOneFileAreRefused) {
    const std::string a = (dir_ / "r.xml").string();
    const std::string b = (dir_ / "." / "r.xml").string();
    EXPECT_EQ(check({{"junit", a}, {"text", b}}), "--output text:" + b + ": " + b +
                                                      " is also the file of --output junit:" + a +
                                                      "; each output needs a file of its own");
}

TEST_F(OutputPaths, APlugInNamedByManyTestsIsRefusedAsAnOutput) {
    // Each path is looked at once however many tests name it; it is protected all the same.
    std::ofstream(dir_ / "plugin.so") << "not really";
    TestSpec test;
    test.path = (dir_ / "plugin.so").string();
    suite_.tests.assign(3, test);
    const std::string problem = check({{"junit", test.path}});
    EXPECT_NE(problem.find("is the test " + test.path), std::string::npos) << problem;
}

TEST_F(OutputPaths, OneOutputGoesToTheStandardOutput) {
    EXPECT_EQ(check({{"json", "-"}, {"junit", (dir_ / "a.xml").string()}}), "");
    EXPECT_EQ(check({{"tap", "/dev/stdout"}}), "");
    EXPECT_EQ(check({{"json", "-"}, {"junit", "/dev/stdout"}}),
              "--output junit:/dev/stdout: --output json:- goes to the standard output already; "
              "one output can go there");
}
