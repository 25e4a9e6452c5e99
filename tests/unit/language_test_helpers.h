// Drives a language backend directly: writes a script, loads it with languages::loadTest and
// runs it against a collector, as the in-process executor would.
#pragma once

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>

#include "build_paths.h"
#include "languages/test_loader.h"

namespace rtf_test {

using namespace robottestingframework;

// A folder of its own for the running GoogleTest test, emptied first.
inline std::filesystem::path scriptFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path folder = std::filesystem::path(build_paths::unitTestTmpDir()) /
                                   "languages" /
                                   (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

inline std::string writeScript(const std::filesystem::path& folder, const std::string& name,
                               const std::string& text, bool executable = false) {
    std::filesystem::path path = folder / name;
    std::ofstream(path) << text;
    if (executable) {
        ::chmod(path.c_str(), 0755);
    }
    return path.string();
}

struct ScriptRun {
    bool loaded = false;
    std::string loadError;
    std::string name;  // the test's name after it ran
    TestStatus status = TestStatus::Passed;
    std::vector<ResultEvent> events;

    // The first event of `kind` whose message or detail contains `text`; nullptr if none.
    const ResultEvent* find(ResultEvent::Kind kind, const std::string& text = "") const {
        for (const auto& event : events) {
            if (event.kind == kind && (event.message.getMessage().find(text) != std::string::npos ||
                                       event.message.getDetail().find(text) != std::string::npos)) {
                return &event;
            }
        }
        return nullptr;
    }
    std::size_t count(ResultEvent::Kind kind) const {
        std::size_t n = 0;
        for (const auto& event : events) {
            n += event.kind == kind ? 1 : 0;
        }
        return n;
    }
};

inline ScriptRun runScript(const std::string& type, const std::string& path,
                           const std::string& param = "", const std::string& environment = "",
                           unsigned int repetition = 1) {
    ScriptRun run;
    std::unique_ptr<languages::LoadedTest> loaded = languages::loadTest(type, path, run.loadError);
    run.loaded = loaded != nullptr;
    if (!loaded) {
        return run;
    }
    TestCase* test = loaded->get();
    test->setParam(param);
    test->setEnvironment(environment);
    test->setRepetition(repetition);
    TestResultCollector collector;
    TestResult result;
    result.addListener(&collector);
    test->run(result);
    run.name = test->getName();
    if (!collector.suites().empty() && !collector.suites().back().tests.empty()) {
        const TestRecord& record = collector.suites().back().tests.back();
        run.status = record.status;
        run.events = record.events;
        if (!record.output.empty()) {  // the collector keeps output apart from the events
            ResultEvent output;
            output.kind = ResultEvent::Kind::Output;
            output.message = TestMessage(record.output);
            run.events.push_back(output);
        }
    }
    return run;
}

}  // namespace rtf_test
