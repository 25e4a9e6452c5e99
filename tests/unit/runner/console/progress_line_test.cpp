// The progress line of a terminal (progress_line.h): k of N, the test that runs, failures so
// far, the ETA from the suites' earlier times, and its place among the console's other lines.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <regex>
#include <string>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "core_test_helpers.h"
#include "runner/console/progress_line.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

// A line drawing into memory, never on its own (no ticker): only events draw it.
class Drawn {
public:
    explicit Drawn(ProgressSettings settings) {
        stream_ = ::open_memstream(&buffer_, &size_);
        settings.redrawMilliseconds = 0;
        line_ = std::make_unique<ProgressLine>(stream_, settings);
    }
    ~Drawn() {
        line_.reset();
        std::fclose(stream_);
        std::free(buffer_);
    }
    ProgressLine* operator->() { return line_.get(); }
    ProgressLine& operator*() { return *line_; }
    std::FILE* stream() { return stream_; }
    // What was written, each running time shown as "(T)".
    std::string written() {
        std::fflush(stream_);
        return std::regex_replace(std::string(buffer_, size_), std::regex("\\(\\d+\\.\\d s\\)"),
                                  "(T)");
    }

private:
    char* buffer_ = nullptr;
    std::size_t size_ = 0;
    std::FILE* stream_ = nullptr;
    std::unique_ptr<ProgressLine> line_;
};

ProgressSettings planned(std::size_t tests) {
    ProgressSettings settings;
    settings.tests = tests;
    return settings;
}

std::string timeless(const std::string& text) {
    return std::regex_replace(text, std::regex("\\(\\d+\\.\\d s\\)"), "(T)");
}

}  // namespace

TEST(ProgressLine, SaysKOfNTheRunningTestAndTheFailuresSoFar) {
    Drawn line(planned(3));
    rtf_test::LambdaTest reach("reach"), grasp("grasp");
    line->testStarted(&reach, "arm", "reach");
    EXPECT_EQ(timeless(line->text()), "[1/3] arm :: reach (T)");
    line->testFailed(&reach);
    line->testEnded(&reach);
    line->testStarted(&grasp, "arm", "grasp");
    EXPECT_EQ(timeless(line->text()), "[2/3] arm :: grasp (T), 1 failed");
}

TEST(ProgressLine, ARetriedTestIsCountedOnceAndItsFailureOnlyIfItFailsAgain) {
    Drawn line(planned(2));
    rtf_test::LambdaTest reach("reach");
    line->testStarted(&reach, "arm", "reach");
    line->testFailed(&reach);
    line->testEnded(&reach);
    line->testRetried(&reach);
    line->testStarted(&reach, "arm", "reach");
    EXPECT_EQ(timeless(line->text()), "[1/2] arm :: reach (T)");
}

TEST(ProgressLine, SeveralRunningShowTheLatestAndHowManyMore) {
    Drawn line(planned(5));
    rtf_test::LambdaTest a("a"), b("b"), c("c");
    line->testStarted(&a, "arm", "a");
    line->testStarted(&b, "leg", "b");
    line->testStarted(&c, "leg", "c");
    line->testRenamed(&c, "joint limits");
    EXPECT_EQ(timeless(line->text()), "[3/5] leg :: joint limits (T) +2 running");
}

TEST(ProgressLine, TheEtaComesFromTheSuitesTimesWhenAnyIsKnown) {
    ProgressSettings settings = planned(4);
    settings.suites = {{"arm", 100}, {"leg", 50}, {"hand", -1}};  // hand: the mean, 75
    Drawn line(settings);
    EXPECT_EQ(line->text(), "[0/4], ETA 3:45");
    line->suiteStarted("arm");
    line->suiteEnded("arm");
    EXPECT_EQ(line->text(), "[0/4], ETA 2:05");
    settings.jobs = 2;  // two lanes: half as long
    Drawn two(settings);
    EXPECT_EQ(two->text(), "[0/4], ETA 1:53");
    Drawn unknown(planned(4));
    EXPECT_EQ(unknown->text(), "[0/4]");
}

TEST(ProgressLine, ALongNameIsCutToTheWidthWithTheCountsKept) {
    ProgressSettings settings = planned(1);
    Drawn line(settings);
    rtf_test::LambdaTest long_("x");
    line->testStarted(&long_, "arm", std::string(200, 'x'));
    line->testFailed(&long_);
    line->testEnded(&long_);
    line->testStarted(&long_, "arm", std::string(200, 'x'));
    const std::string text = line->text();
    EXPECT_EQ(text.size(), 79u) << text;  // not a terminal: 80 columns, less one
    EXPECT_NE(text.find("..., 1 failed"), std::string::npos) << text;
}

TEST(ProgressLine, FailuresAreRedWithColours) {
    ProgressSettings settings = planned(1);
    settings.colours = true;
    Drawn line(settings);
    rtf_test::LambdaTest reach("reach");
    line->testStarted(&reach, "arm", "reach");
    line->testFailed(&reach);
    line->testEnded(&reach);
    EXPECT_EQ(line->text(), "[1/1], \033[31m1 failed\033[0m");
}

TEST(ProgressLine, OnTheOrderedStreamTheConsolesLinesComeBetweenErasingAndDrawing) {
    Drawn line(planned(2));
    // The console of -j 1 between the two listeners: it prints what it gets as a line.
    class LineConsole : public TestListener {
    public:
        explicit LineConsole(std::FILE* stream) : stream_(stream) {}
        void startTest(const robottestingframework::Test* test) override {
            std::fprintf(stream_, "start %s\n", test->getName().c_str());
        }

    private:
        std::FILE* stream_;
    } console(line.stream());
    TestResult result;
    result.addListener(&line->before());
    result.addListener(&console);
    result.addListener(&line->after());
    TestSuite suite("arm");
    rtf_test::LambdaTest reach("reach"), grasp("grasp");
    result.startTestRunner();
    result.startTestSuite(&suite);
    result.startTest(&reach);
    result.addFailure(&reach, TestMessage("no"));
    result.endTest(&reach);
    result.startTest(&grasp);
    result.endTestRunner();
    EXPECT_EQ(line.written(),
              "[0/2]"                                        // startTestRunner
              "\r\033[K[0/2]"                                // startTestSuite
              "\r\033[Kstart reach\n[1/2] arm :: reach (T)"  // startTest
              "\r\033[K[1/2] arm :: reach (T)"               // addFailure
              "\r\033[K[1/2], 1 failed"                      // endTest
              "\r\033[Kstart grasp\n[2/2] arm :: grasp (T), 1 failed"
              "\r\033[K");  // endTestRunner: erased, not drawn again
}

TEST(ProgressLine, ARecordThePlanDidNotKnowNeverShowsMoreStartedThanPlanned) {
    // A world process that did not stop cleanly is a record of its own after the suite's tests.
    Drawn line(planned(1));
    rtf_test::LambdaTest reach("reach"), stop("world 'lab': stop of 'server'");
    line->testStarted(&reach, "arm", "reach");
    line->testEnded(&reach);
    line->testStarted(&stop, "arm", "world 'lab': stop of 'server'");
    EXPECT_EQ(timeless(line->text()), "[2/2] arm :: world 'lab': stop of 'server' (T)");
}
