// One rule for repetitions and seconds, whether from the command line or a suite file.
#include <gtest/gtest.h>

#include "runner/model/value_limits.h"

using namespace robottestingframework::runner;

TEST(Numbers, TheRunnersRepetitionTakesRtf2sDefaultZeroAsNotGiven) {
    unsigned int runs = 5;
    EXPECT_EQ(checkRunnerRepetition("0", runs), "");
    EXPECT_EQ(runs, 0u);
    EXPECT_EQ(checkRunnerRepetition(" 00 ", runs), "");
    EXPECT_EQ(runs, 0u);
    EXPECT_EQ(checkRunnerRepetition("3", runs), "");
    EXPECT_EQ(runs, 3u);
    EXPECT_EQ(checkRunnerRepetition("zero", runs), "is not a whole number of runs >= 1");
    EXPECT_EQ(checkRunnerRepetition("-1", runs), "is not a whole number of runs >= 1");
    EXPECT_EQ(checkRunnerRepetition("1000000001", runs), "is too large: at most 1000000000 runs");
}

TEST(Numbers, RepetitionIsAWholeNumberUpToTheLimit) {
    unsigned int runs = 0;
    EXPECT_EQ(checkRepetition(" 7 ", runs), "");
    EXPECT_EQ(runs, 7u);
    EXPECT_EQ(checkRepetition("1000000000", runs), "");
    for (const char* bad : {"0", "-1", "2.5", "", "abc"}) {
        EXPECT_EQ(checkRepetition(bad, runs), "is not a whole number of runs >= 1") << bad;
    }
    for (const char* large : {"1000000001", "99999999999", "999999999999999999999999"}) {
        EXPECT_EQ(checkRepetition(large, runs), "is too large: at most 1000000000 runs") << large;
    }
}

TEST(Numbers, SecondsAreFiniteAndUpToTheLimit) {
    double seconds = -1;
    EXPECT_EQ(checkSeconds("2.5", seconds), "");
    EXPECT_EQ(seconds, 2.5);
    EXPECT_EQ(checkSeconds("0", seconds), "");
    EXPECT_EQ(seconds, 0);
    for (const char* bad : {"inf", "-inf", "nan", "1e999", "-1", "", "soon"}) {
        EXPECT_EQ(checkSeconds(bad, seconds).rfind("is not a number of seconds >= 0", 0), 0u)
            << bad;
    }
    EXPECT_EQ(checkSeconds("1000001", seconds),
              "is too large: at most 1000000 seconds (0 for no limit)");
}

TEST(Numbers, RetriesAreAWholeNumberFromZeroToTheLimit) {
    unsigned int retries = 9;
    EXPECT_EQ(checkRetries("0", retries), "");
    EXPECT_EQ(retries, 0u);
    EXPECT_EQ(checkRetries(" 100 ", retries), "");
    EXPECT_EQ(retries, 100u);
    for (const char* bad : {"-1", "2.5", "", "abc"}) {
        EXPECT_EQ(checkRetries(bad, retries), "is not a whole number of retries from 0 to 100")
            << bad;
    }
    EXPECT_EQ(checkRetries("101", retries), "is too large: at most 100 retries");
    EXPECT_EQ(checkRetries("99999999999999999999999", retries),
              "is too large: at most 100 retries");
}
