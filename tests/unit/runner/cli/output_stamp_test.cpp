// outputStamp / outputWrittenMeanwhile: an output file another process wrote during the run is
// told from one left as it was, or one the run itself made.
#include "runner/cli/output_stamp.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "build_paths.h"

namespace fs = std::filesystem;
using robottestingframework::runner::outputStamp;
using robottestingframework::runner::outputWrittenMeanwhile;

namespace {

class OutputStamp : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) / ("stamp_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    // Written whole under another name and renamed into place, as every report is.
    std::string replace(const std::string& name, const std::string& text) {
        const fs::path path = dir_ / name;
        std::ofstream(dir_ / (name + ".tmp"), std::ios::binary) << text;
        fs::rename(dir_ / (name + ".tmp"), path);
        return path.string();
    }
    fs::path dir_;
};

}  // namespace

TEST_F(OutputStamp, NoFileHasNoStampAndIsNotSaid) {
    const std::string path = (dir_ / "result.txt").string();
    EXPECT_EQ(outputStamp(path), "");
    EXPECT_EQ(outputWrittenMeanwhile("text", path, ""), "");
}

TEST_F(OutputStamp, AFileLeftAsItWasIsNotSaid) {
    const std::string path = replace("result.txt", "an earlier run");
    const std::string before = outputStamp(path);
    EXPECT_FALSE(before.empty());
    EXPECT_EQ(outputWrittenMeanwhile("text", path, before), "");
}

TEST_F(OutputStamp, AFileWrittenMeanwhileIsSaid) {
    const std::string path = replace("result.txt", "an earlier run");
    const std::string before = outputStamp(path);
    replace("result.txt", "another run");
    const std::string said = outputWrittenMeanwhile("text", path, before);
    EXPECT_EQ(
        said.rfind(
            "the text output " + path + " was written by another run while this one ran (at ", 0),
        0u)
        << said;
    EXPECT_NE(said.find("): this run's replaces it"), std::string::npos) << said;
}

TEST_F(OutputStamp, AFileMadeMeanwhileIsSaid) {
    const std::string path = (dir_ / "r.xml").string();
    const std::string before = outputStamp(path);
    replace("r.xml", "<testsuites/>");
    EXPECT_NE(outputWrittenMeanwhile("junit", path, before), "");
}

TEST_F(OutputStamp, ADeviceIsWrittenThroughAndNeverSaid) {
    EXPECT_EQ(outputStamp("/dev/null"), "");
    EXPECT_EQ(outputWrittenMeanwhile("text", "/dev/null", "something"), "");
}
