// Which shard a machine runs (shard_of_this_machine.h): flags first, then the CI engines'
// variables.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "runner/plan/shard_of_this_machine.h"

using namespace robottestingframework::runner;

namespace {

struct Environment {
    std::map<std::string, std::string> variables;
    EnvironmentLookup lookup() const {
        return [this](const char* name) -> const char* {
            auto found = variables.find(name);
            return found == variables.end() ? nullptr : found->second.c_str();
        };
    }
};

ShardChoice choose(const ShardFlags& flags, const Environment& environment,
                   std::string* error = nullptr) {
    ShardChoice choice;
    std::string problem;
    const bool ok = chooseShard(flags, environment.lookup(), choice, problem);
    if (error != nullptr) {
        *error = ok ? "" : problem;
    } else {
        EXPECT_TRUE(ok) << problem;
    }
    return choice;
}

std::string failure(const ShardFlags& flags, const Environment& environment) {
    std::string error;
    choose(flags, environment, &error);
    return error;
}

}  // namespace

TEST(ShardChoice, NothingSetIsNotSharded) {
    EXPECT_FALSE(choose({}, {}).sharded);
}

TEST(ShardChoice, EachEngineConvention) {
    struct Case {
        std::map<std::string, std::string> variables;
        unsigned int index;
        unsigned int count;
        const char* engine;
    };
    const Case cases[] = {
        {{{"TEST_SHARD_INDEX", "2"}, {"TEST_TOTAL_SHARDS", "4"}}, 2, 4, "Bazel"},
        {{{"GTEST_SHARD_INDEX", "0"}, {"GTEST_TOTAL_SHARDS", "3"}}, 0, 3, "GoogleTest"},
        {{{"CI_NODE_INDEX", "4"}, {"CI_NODE_TOTAL", "4"}}, 3, 4, "GitLab CI"},  // 1-based
        {{{"JOB_COMPLETION_INDEX", "1"}, {"RTF_SHARD_COUNT", "2"}}, 1, 2, "Kubernetes"},
    };
    for (const Case& c : cases) {
        const ShardChoice choice = choose({}, Environment{c.variables});
        EXPECT_TRUE(choice.sharded) << c.engine;
        EXPECT_EQ(choice.index, c.index) << c.engine;
        EXPECT_EQ(choice.count, c.count) << c.engine;
        EXPECT_NE(choice.source.find(c.engine), std::string::npos) << choice.source;
    }
}

TEST(ShardChoice, ExplicitFlagsWinOverTheEnvironment) {
    const ShardChoice choice =
        choose({"1", "2"}, Environment{{{"CI_NODE_INDEX", "5"}, {"CI_NODE_TOTAL", "9"}}});
    EXPECT_EQ(choice.index, 1u);
    EXPECT_EQ(choice.count, 2u);
    EXPECT_EQ(choice.source, "--shard-index 1 --shard-count 2");
}

TEST(ShardChoice, GitLabWithoutParallelAndAnIndexedJobWithoutACountAreNotShards) {
    EXPECT_FALSE(choose({}, Environment{{{"CI_NODE_TOTAL", "1"}}}).sharded);
    EXPECT_FALSE(choose({}, Environment{{{"JOB_COMPLETION_INDEX", "3"}}}).sharded);
}

TEST(ShardChoice, AgreeingConventionsAreFine) {
    const ShardChoice choice = choose({}, Environment{{{"TEST_SHARD_INDEX", "1"},
                                                       {"TEST_TOTAL_SHARDS", "3"},
                                                       {"GTEST_SHARD_INDEX", "1"},
                                                       {"GTEST_TOTAL_SHARDS", "3"}}});
    EXPECT_EQ(choice.index, 1u);
    EXPECT_NE(choice.source.find("Bazel"), std::string::npos);
}

TEST(ShardChoice, ConflictingVariablesNameBoth) {
    const std::string error = failure({}, Environment{{{"TEST_SHARD_INDEX", "1"},
                                                       {"TEST_TOTAL_SHARDS", "3"},
                                                       {"CI_NODE_INDEX", "1"},
                                                       {"CI_NODE_TOTAL", "3"}}});
    EXPECT_NE(error.find("conflicting"), std::string::npos) << error;
    EXPECT_NE(error.find("TEST_SHARD_INDEX=1"), std::string::npos) << error;
    EXPECT_NE(error.find("CI_NODE_INDEX=1"), std::string::npos) << error;
}

TEST(ShardChoice, BadValuesNameTheFlagOrVariable) {
    EXPECT_EQ(
        failure({"4", "4"}, {}).rfind("--shard-index '4': expected a whole number from 0 to 3", 0),
        0u);
    EXPECT_EQ(failure({"0", "0"}, {}).rfind("--shard-count '0'", 0), 0u);
    EXPECT_EQ(failure({"x", "2"}, {}).rfind("--shard-index 'x'", 0), 0u);
    EXPECT_EQ(failure({"-1", "2"}, {}).rfind("--shard-index '-1'", 0), 0u);
    EXPECT_EQ(failure({"1", ""}, {}), "--shard-index needs --shard-count");
    EXPECT_EQ(failure({"", "2"}, {}), "--shard-count needs --shard-index");
    EXPECT_EQ(failure({}, Environment{{{"CI_NODE_INDEX", "0"}, {"CI_NODE_TOTAL", "2"}}})
                  .rfind("CI_NODE_INDEX '0': expected a whole number from 1 to 2", 0),
              0u);
    EXPECT_EQ(failure({}, Environment{{{"GTEST_SHARD_INDEX", "1"}, {"GTEST_TOTAL_SHARDS", "two"}}})
                  .rfind("GTEST_TOTAL_SHARDS 'two'", 0),
              0u);
    EXPECT_EQ(failure({}, Environment{{{"TEST_TOTAL_SHARDS", "2"}}})
                  .rfind("TEST_TOTAL_SHARDS is "
                         "set but TEST_SHARD_INDEX",
                         0),
              0u);
    EXPECT_EQ(failure({}, Environment{{{"RTF_SHARD_COUNT", "2"}}})
                  .rfind("RTF_SHARD_COUNT is set but JOB_COMPLETION_INDEX is not", 0),
              0u);
}
