// Small doubles shared by the core's unit tests: a test case made of lambdas, a fixture that
// logs its calls, and the collected events as readable lines.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResultCollector.h>

#include "build_paths.h"

namespace rtf_test {

using namespace robottestingframework;

// "kind name: message" for every collected event (": message" only when there is one).
inline std::vector<std::string> eventLines(const TestResultCollector& collector) {
    std::vector<std::string> lines;
    for (const ResultEvent& event : collector.getResults()) {
        std::string line = std::string(toString(event.kind)) + " " + event.testName;
        if (!event.message.getMessage().empty()) {
            line += ": " + event.message.getMessage();
        }
        lines.push_back(line);
    }
    return lines;
}

inline bool contains(const std::vector<std::string>& lines, const std::string& line) {
    for (const std::string& l : lines) {
        if (l == line) {
            return true;
        }
    }
    return false;
}

class LambdaTest : public TestCase {
public:
    explicit LambdaTest(
        std::string name, std::function<void()> body = [] {})
        : TestCase(std::move(name)), body(std::move(body)) {}
    using TestCase::run;  // run(TestResult&), hidden by run() below
    bool setup(int argc, char** argv) override {
        log.push_back("setup");
        for (int i = 0; i < argc; ++i) {
            args.push_back(argv[i]);
        }
        return onSetup ? onSetup() : true;
    }
    void run() override {
        log.push_back("run");
        body();
    }
    void tearDown() override {
        log.push_back("tearDown");
        if (onTearDown) {
            onTearDown();
        }
    }

    std::function<void()> body;
    std::function<bool()> onSetup;
    std::function<void()> onTearDown;
    std::vector<std::string> log;
    std::vector<std::string> args;
};

class LoggingFixture : public FixtureManager {
public:
    LoggingFixture(std::string name, std::vector<std::string>& log) : log(log) {
        setName(std::move(name));
    }
    bool setup(int argc, char** argv) override {
        log.push_back("setup " + getName());
        args.assign(argv, argv + argc);
        if (throwInSetup) {
            throw std::runtime_error("boom");
        }
        return setupResult;
    }
    bool check() override {
        ++checks;
        return checkResult;
    }
    void tearDown() override { log.push_back("tearDown " + getName()); }

    std::vector<std::string>& log;
    std::vector<std::string> args;
    bool setupResult = true;
    bool throwInSetup = false;
    bool checkResult = true;
    int checks = 0;
};

// A fresh folder under the build tree for one test's files.
inline std::filesystem::path scratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path dir = std::filesystem::path(build_paths::unitTestTmpDir()) /
                                (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace rtf_test
