// The cache folder of --lf and --ff: what a run keeps of the last one, and how it is written.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "build_paths.h"
#include "runner/cli/last_run_cache.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

class LastRunCache : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) / ("cache_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

}  // namespace

TEST(LastFailedUpdate, AddsTheFailuresTakesOutThePassesAndKeepsTheTestsNotRun) {
    const std::set<std::string> previous{"s/a", "s/b", "s/c", "s/d"};
    const std::set<std::string> now = updatedLastFailed(previous, {{"s/a", "passed"},
                                                                   {"s/b", "skipped"},
                                                                   {"s/c", "interrupted"},
                                                                   {"s/e", "timed out"},
                                                                   {"s/f", "crashed"},
                                                                   {"s/g", "error"},
                                                                   {"s/h", "flaky"},
                                                                   {"s/i", "failed"}});
    EXPECT_EQ(now, (std::set<std::string>{"s/c", "s/d", "s/e", "s/f", "s/g", "s/i"}));
}

TEST_F(LastRunCache, WritesTheFolderWithItsGitignoreAndReadmeAndReadsItBack) {
    const fs::path folder = dir_ / "nested" / ".rtf_cache";
    std::string error;
    ASSERT_TRUE(writeLastFailed(folder.string(), {"s/a", "s/t[--speed 80]"}, error)) << error;
    EXPECT_EQ(contents(folder / ".gitignore").find("\n*\n") != std::string::npos, true);
    EXPECT_NE(contents(folder / "README.md").find("--lf"), std::string::npos);
    EXPECT_EQ(contents(folder / "lastfailed"), "s/a\ns/t[--speed 80]\n");
    std::set<std::string> ids;
    ASSERT_TRUE(readLastFailed(folder.string(), ids, error)) << error;
    EXPECT_EQ(ids, (std::set<std::string>{"s/a", "s/t[--speed 80]"}));
    // Written again: replaced whole, and no temporary file is left beside it.
    ASSERT_TRUE(writeLastFailed(folder.string(), {}, error)) << error;
    EXPECT_EQ(contents(folder / "lastfailed"), "");
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        (void)entry;
        ++files;
    }
    EXPECT_EQ(files, 3u);
}

TEST_F(LastRunCache, AMissingCacheHasNoFailures) {
    std::set<std::string> ids;
    std::string error;
    EXPECT_TRUE(readLastFailed((dir_ / "none").string(), ids, error)) << error;
    EXPECT_TRUE(ids.empty());
}

TEST_F(LastRunCache, AFolderThatCannotBeMadeIsAnErrorNamingIt) {
    std::ofstream(dir_ / "file") << "x";
    std::string error;
    EXPECT_FALSE(writeLastFailed((dir_ / "file" / "cache").string(), {"s/a"}, error));
    EXPECT_NE(error.find("cannot make the cache folder"), std::string::npos) << error;
}
