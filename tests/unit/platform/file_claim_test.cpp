// platform::FileClaim: a file one process at a time writes (a world's process log): a second
// claim, from another process or from this one, finds it busy until the first lets it go.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "build_paths.h"
#include "platform/file_claim.h"

namespace fs = std::filesystem;
using robottestingframework::platform::FileClaim;

namespace {

class FileClaimTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) / ("claim_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

}  // namespace

TEST_F(FileClaimTest, MakesTheFileAndHoldsIt) {
    const std::string path = (dir_ / "a.log").string();
    FileClaim claim;
    bool busy = true;
    std::string error;
    ASSERT_TRUE(claim.take(path, busy, error)) << error;
    EXPECT_FALSE(busy);
    EXPECT_TRUE(claim.held());
    EXPECT_TRUE(fs::is_regular_file(path));
    EXPECT_EQ(fs::file_size(path), 0u);
}

TEST_F(FileClaimTest, ASecondClaimIsBusyUntilTheFirstIsLetGo) {
    const std::string path = (dir_ / "a.log").string();
    FileClaim first, second;
    bool busy = false;
    std::string error;
    ASSERT_TRUE(first.take(path, busy, error)) << error;
    EXPECT_FALSE(second.take(path, busy, error));
    EXPECT_TRUE(busy);
    EXPECT_TRUE(error.empty()) << error;
    EXPECT_FALSE(second.held());
    first.release();
    EXPECT_TRUE(second.take(path, busy, error)) << error;
    EXPECT_FALSE(busy);
}

TEST_F(FileClaimTest, AnotherProcessFindsItBusy) {
    const std::string path = (dir_ / "a.log").string();
    FileClaim claim;
    bool busy = false;
    std::string error;
    ASSERT_TRUE(claim.take(path, busy, error)) << error;
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        claim.release();  // the child's copy of the descriptor: the parent's lock stays
        FileClaim other;
        bool otherBusy = false;
        std::string otherError;
        const bool took = other.take(path, otherBusy, otherError);
        ::_exit(!took && otherBusy ? 0 : 1);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

TEST_F(FileClaimTest, AFolderThatIsNotThereIsAnError) {
    FileClaim claim;
    bool busy = true;
    std::string error;
    EXPECT_FALSE(claim.take((dir_ / "missing" / "a.log").string(), busy, error));
    EXPECT_FALSE(busy);
    EXPECT_FALSE(error.empty());
}
