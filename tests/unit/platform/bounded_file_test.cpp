// platform::readBoundedFile: every input file the runner reads is a regular file (or a pipe
// where one is read) of a bounded size; anything else is an error naming it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "build_paths.h"
#include "platform/bounded_file.h"

namespace fs = std::filesystem;
using robottestingframework::platform::Pipes;
using robottestingframework::platform::readBoundedFile;

namespace {

class BoundedFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) / ("bounded_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path.string();
    }
    fs::path dir_;
};

}  // namespace

TEST_F(BoundedFile, ReadsARegularFileUpToTheLimit) {
    const std::string path = write("r.xml", "12345678");
    std::string content;
    std::string error;
    ASSERT_TRUE(readBoundedFile(path, "report", 8, Pipes::Refused, content, error)) << error;
    EXPECT_EQ(content, "12345678");
    EXPECT_FALSE(readBoundedFile(path, "report", 7, Pipes::Read, content, error));
    EXPECT_EQ(error, path + ": the report is larger than 7 bytes, the limit of a report");
}

TEST_F(BoundedFile, RefusesADeviceAFolderAndAMissingFile) {
    std::string content;
    std::string error;
    EXPECT_FALSE(readBoundedFile("/dev/zero", "report", 1024, Pipes::Read, content, error));
    EXPECT_EQ(error,
              "/dev/zero: is a character device, not a report (a report is a regular file or a "
              "pipe)");
    EXPECT_FALSE(
        readBoundedFile(dir_.string(), "suite file", 1024, Pipes::Refused, content, error));
    EXPECT_EQ(error, dir_.string() + ": is a folder, not a suite file");
    EXPECT_FALSE(readBoundedFile((dir_ / "missing").string(), "variable file", 1024, Pipes::Read,
                                 content, error));
    EXPECT_NE(error.find("missing: cannot read the variable file ("), std::string::npos) << error;
}

TEST_F(BoundedFile, ReadsAPipeOnceAndBoundsIt) {
    int ends[2];
    ASSERT_EQ(::pipe(ends), 0);
    const std::string path = "/dev/fd/" + std::to_string(ends[0]);
    ASSERT_EQ(::write(ends[1], "0123456789", 10), 10);
    ::close(ends[1]);
    std::string content;
    std::string error;
    EXPECT_FALSE(readBoundedFile(path, "report", 1024, Pipes::Refused, content, error));
    EXPECT_NE(error.find("is a FIFO (named pipe), not a report (a report is a regular file)"),
              std::string::npos)
        << error;
    EXPECT_FALSE(readBoundedFile(path, "report", 4, Pipes::Read, content, error));
    EXPECT_EQ(error, path + ": the report is larger than 4 bytes, the limit of a report");
    ::close(ends[0]);

    ASSERT_EQ(::pipe(ends), 0);
    const std::string again = "/dev/fd/" + std::to_string(ends[0]);
    ASSERT_EQ(::write(ends[1], "<r/>", 4), 4);
    ::close(ends[1]);
    ASSERT_TRUE(readBoundedFile(again, "report", 1024, Pipes::Read, content, error)) << error;
    EXPECT_EQ(content, "<r/>");
    ::close(ends[0]);
}
