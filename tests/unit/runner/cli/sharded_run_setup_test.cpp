// A sharded run before it starts (cli/sharded_run_setup.h): the shard from the flags and this
// process's environment, Bazel's conventions, the shard variables taken out of the tests'
// environment, and each suite's shard.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_paths.h"
#include "runner/cli/sharded_run_setup.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

// Sets the shard variables a test asks for and puts the whole environment back afterwards
// (TMPDIR too, which Bazel's TEST_TMPDIR moves).
class ShardSetup : public ::testing::Test {
protected:
    void SetUp() override {
        for (const auto& name : shardVariables()) {
            remember(name);
            ::unsetenv(name.c_str());
        }
        remember("TMPDIR");
        remember("TEST_TMPDIR");
        ::unsetenv("TEST_TMPDIR");
        dir_ =
            fs::path(build_paths::unitTestTmpDir()) / ("shard_setup_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        for (const auto& [name, value] : saved_) {
            if (value) {
                ::setenv(name.c_str(), value->c_str(), 1);
            } else {
                ::unsetenv(name.c_str());
            }
        }
        fs::remove_all(dir_);
    }
    void remember(const std::string& name) {
        const char* value = std::getenv(name.c_str());
        saved_[name] = value != nullptr ? std::optional<std::string>(value) : std::nullopt;
    }
    static void set(const char* name, const std::string& value) {
        ::setenv(name, value.c_str(), 1);
    }

    std::map<std::string, std::optional<std::string>> saved_;
    fs::path dir_;
};

SuiteSpec suite(const std::string& name, const std::string& lock = "") {
    SuiteSpec spec;
    spec.name = name;
    spec.where.file = name + ".xml";
    if (!lock.empty()) {
        spec.resources.push_back(ResourceSpec{lock, "", 1, {}});
    }
    return spec;
}

}  // namespace

TEST_F(ShardSetup, FlagsChooseTheShard) {
    Options options;
    options.shard = ShardFlags{"1", "3"};
    ShardChoice choice;
    std::string error;
    ASSERT_TRUE(prepareShard(options, choice, error)) << error;
    EXPECT_TRUE(choice.sharded);
    EXPECT_EQ(choice.index, 1u);
    EXPECT_EQ(choice.count, 3u);
}

TEST_F(ShardSetup, NothingGivenIsNotSharded) {
    Options options;
    ShardChoice choice;
    std::string error;
    ASSERT_TRUE(prepareShard(options, choice, error)) << error;
    EXPECT_FALSE(choice.sharded);
    EXPECT_TRUE(options.outputs.empty());
}

TEST_F(ShardSetup, AnIndexNotBelowTheCountIsAnError) {
    Options options;
    options.shard = ShardFlags{"3", "3"};
    ShardChoice choice;
    std::string error;
    EXPECT_FALSE(prepareShard(options, choice, error));
    EXPECT_NE(error.find("--shard-index"), std::string::npos) << error;
}

TEST_F(ShardSetup, TheEnvironmentsShardIsTakenThenRemovedFromTheTestsEnvironment) {
    set("GTEST_SHARD_INDEX", "1");
    set("GTEST_TOTAL_SHARDS", "2");
    Options options;
    ShardChoice choice;
    std::string error;
    ASSERT_TRUE(prepareShard(options, choice, error)) << error;
    EXPECT_TRUE(choice.sharded);
    EXPECT_EQ(choice.index, 1u);
    EXPECT_EQ(choice.count, 2u);
    EXPECT_EQ(std::getenv("GTEST_SHARD_INDEX"), nullptr);
    EXPECT_EQ(std::getenv("GTEST_TOTAL_SHARDS"), nullptr);
}

TEST_F(ShardSetup, BazelGetsAJUnitOutputWhereItCollectsIt) {
    const std::string xml = (dir_ / "test.xml").string();
    set("XML_OUTPUT_FILE", xml);
    Options options;
    options.outputs.push_back(OutputRequest{"text", "result.txt"});
    ShardChoice choice;
    std::string error;
    ASSERT_TRUE(prepareShard(options, choice, error)) << error;
    ASSERT_EQ(options.outputs.size(), 2u);
    EXPECT_EQ(options.outputs[1].type, "junit");
    EXPECT_EQ(options.outputs[1].file, xml);
    EXPECT_EQ(std::getenv("XML_OUTPUT_FILE"), nullptr);
}

TEST_F(ShardSetup, BazelsJUnitOutputAlreadyAskedForIsNotAddedTwice) {
    const std::string xml = (dir_ / "test.xml").string();
    set("XML_OUTPUT_FILE", xml);
    Options options;
    options.outputs.push_back(OutputRequest{"junit", xml});
    ShardChoice choice;
    std::string error;
    ASSERT_TRUE(prepareShard(options, choice, error)) << error;
    EXPECT_EQ(options.outputs.size(), 1u);
}

TEST_F(ShardSetup, BazelsScratchFolderBecomesTheTestsTmpdir) {
    set("TEST_TMPDIR", dir_.string());
    Options options;
    ShardChoice choice;
    std::string error;
    ASSERT_TRUE(prepareShard(options, choice, error)) << error;
    ASSERT_NE(std::getenv("TMPDIR"), nullptr);
    EXPECT_EQ(std::string(std::getenv("TMPDIR")), dir_.string());
}

TEST_F(ShardSetup, AShardedRunTouchesBazelsShardStatusFile) {
    const fs::path status = dir_ / "shard_status";
    set("TEST_SHARD_STATUS_FILE", status.string());
    set("TEST_SHARD_INDEX", "0");
    set("TEST_TOTAL_SHARDS", "2");
    Options options;
    ShardChoice choice;
    std::string error;
    ASSERT_TRUE(prepareShard(options, choice, error)) << error;
    EXPECT_TRUE(fs::exists(status));
    EXPECT_EQ(std::getenv("TEST_SHARD_STATUS_FILE"), nullptr);
}

TEST_F(ShardSetup, AnUnshardedRunLeavesTheShardStatusFileAlone) {
    const fs::path status = dir_ / "shard_status";
    set("TEST_SHARD_STATUS_FILE", status.string());
    Options options;
    ShardChoice choice;
    std::string error;
    ASSERT_TRUE(prepareShard(options, choice, error)) << error;
    EXPECT_FALSE(fs::exists(status));
}

TEST_F(ShardSetup, AShardStatusFileThatCannotBeWrittenIsAnErrorNamingIt) {
    const std::string status = (dir_ / "no" / "such" / "status").string();
    set("TEST_SHARD_STATUS_FILE", status);
    Options options;
    options.shard = ShardFlags{"0", "2"};
    ShardChoice choice;
    std::string error;
    EXPECT_FALSE(prepareShard(options, choice, error));
    EXPECT_EQ(error, "TEST_SHARD_STATUS_FILE " + status + ": cannot be written");
}

TEST_F(ShardSetup, SuitesAreSplitInTheOrderOfTheirNames) {
    EXPECT_EQ(shardsOf({suite("c"), suite("a"), suite("b")}, 2, std::nullopt),
              (std::vector<unsigned int>{0, 0, 1}));
}

TEST_F(ShardSetup, SuitesSharingALockAreInOneShard) {
    const auto shards = shardsOf({suite("a", "robot"), suite("b"), suite("c", "robot"), suite("d")},
                                 2, std::nullopt);
    EXPECT_EQ(shards[0], shards[2]);
}

TEST_F(ShardSetup, DurationsAreTheSuitesTimesInTheReport) {
    const std::string report = (dir_ / "earlier.xml").string();
    std::ofstream(report) << R"(<?xml version="1.0" encoding="UTF-8"?>
<testsuites name="RobotTestingFramework" tests="0" failures="0" errors="0" time="12">
  <testsuite name="a" tests="0" time="1" id="0"/>
  <testsuite name="b" tests="0" time="1" id="1"/>
  <testsuite name="c" tests="0" time="10" id="2"/>
</testsuites>
)";
    // Without durations a and c share shard 0; with them c, the longest, is alone.
    EXPECT_EQ(shardsOf({suite("a"), suite("b"), suite("c")}, 2, std::nullopt),
              (std::vector<unsigned int>{0, 1, 0}));
    EXPECT_EQ(shardsOf({suite("a"), suite("b"), suite("c")}, 2, suiteDurations(report)),
              (std::vector<unsigned int>{1, 1, 0}));
}

TEST_F(ShardSetup, DurationsThatCannotBeReadThrowNamingTheReport) {
    const std::string report = (dir_ / "missing.xml").string();
    try {
        suiteDurations(report);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("--durations-from " + report), std::string::npos)
            << e.what();
    }
}

TEST_F(ShardSetup, SuitesLinkedByDependsAreInOneShard) {
    // Round-robin over a, b, c would put b on shard 1; its test depends on a's.
    std::vector<SuiteSpec> suites{suite("a"), suite("b"), suite("c")};
    TestSpec base;
    base.name = "base";
    suites[0].tests.push_back(base);
    TestSpec uses;
    uses.name = "uses";
    uses.depends = {"base"};
    suites[1].tests.push_back(uses);
    const std::vector<unsigned int> shards = shardsOf(suites, 2, std::nullopt);
    EXPECT_EQ(shards[0], shards[1]);
    EXPECT_NE(shards[2], shards[0]);
}

TEST_F(ShardSetup, ThePlanIdentityIsTheWholeSelections) {
    std::vector<SuiteSpec> suites{suite("a"), suite("b")};
    const std::string plan = planIdentity(suites, 2);
    EXPECT_EQ(plan.size(), 16U);
    EXPECT_EQ(plan.find_first_not_of("0123456789abcdef"), std::string::npos);
    EXPECT_EQ(planIdentity(suites, 2), plan);  // the same on every machine
    std::vector<SuiteSpec> elsewhere{suite("a"), suite("b")};
    for (auto& moved : elsewhere) {
        moved.where.file = "/builds/runner-7/" + moved.where.file.str();  // another checkout
    }
    EXPECT_EQ(planIdentity(elsewhere, 2), plan);
    EXPECT_NE(planIdentity(suites, 3), plan);
    EXPECT_NE(planIdentity({suite("a"), suite("c")}, 2), plan);
    suites[1].tests.emplace_back();
    suites[1].tests.back().id = "t";
    EXPECT_NE(planIdentity(suites, 2), plan);
}
