// A report of this runner read back, JUnit XML or JSON (CTRF): what --rerun-failed (the failed
// tests), --durations (each suite's time) and --merge (the whole document) read. Strict: a file
// this runner did not write, or one cut short or edited out of shape, is an error naming the
// file, the line when known, and what was expected.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

namespace robottestingframework {
namespace runner {

enum class ReportFormat { JUnit, Json };

struct ReportedTest {
    std::string suite;  // empty for tests run outside a suite
    std::string name;
    std::string state;          // as TestStatus's toString spells it: "passed", "timed out", ...
    double seconds = 0;         // every attempt's
    unsigned int attempts = 1;  // 1 + its retries
};

struct ReportedSuite {
    std::string name;
    double seconds = 0;  // fixtures included when the report says so
};

// Which shard wrote the report (JUnit <properties>, CTRF results.extra["robotology.rtf"].shard).
struct ReportedShard {
    bool known = false;
    unsigned int index = 0;
    unsigned int count = 0;
    std::string plan;    // the whole run's plan identity; empty in reports of earlier versions
    bool rerun = false;  // written by --rerun-failed: it replaces tests of an earlier report
};

struct Report {
    std::string path;
    ReportFormat format = ReportFormat::JUnit;
    ReportedShard shard;
    std::vector<ReportedTest> tests;
    std::vector<ReportedSuite> suites;
    // The document itself, for --merge: one of the two, by `format`.
    std::shared_ptr<pugi::xml_document> junit;
    nlohmann::ordered_json json;
};

// Reads `path`. `option` starts the error messages ("--durations"). Throws std::runtime_error
// "OPTION FILE:LINE: ..." when the file is missing, unreadable, not JUnit or JSON, not written by
// this runner, or out of shape.
Report readReport(const std::string& option, const std::string& path);

// The largest report readReport and readImportedReport read (a regular file or a pipe, such as
// the shell's `<(...)`): a run's outputs are capped far below it (README: output limits).
constexpr std::size_t maxReportBytes = 256 * 1024 * 1024;

// The same from text already read; `path` names it in messages.
Report parseReport(const std::string& option, const std::string& text, const std::string& path);

// The state of a JUnit <testcase> of this runner ("timed out"): its status= in the reports of
// earlier versions, else read from its elements (<failure type="timeout">, <flakyFailure>, ...).
std::string junitTestState(pugi::xml_node test);
// True for the <testcase> a failed fixture adds to its suite (<error type="fixture">).
bool isJUnitFixtureCase(pugi::xml_node test);
// False for the <testsuite> that only holds an empty shard's properties (no id, no testcase).
bool isJUnitRunSuite(pugi::xml_node suite);

// The JUnit <property> names and CTRF keys of the shard a report comes from.
extern const char* const shardIndexProperty;  // "rtf.shard.index"
extern const char* const shardCountProperty;  // "rtf.shard.count"
extern const char* const shardPlanProperty;   // "rtf.shard.plan"
extern const char* const rerunProperty;       // "rtf.rerun"
// The key of the runner's extensions in each CTRF "extra" object (json_reporter.cpp writes it),
// namespaced as the CTRF specification recommends (an owner's prefix and a delimiter). Reports
// of earlier versions used "rtf": readReport moves it to this key.
extern const char* const ctrfExtensionKey;  // "robotology.rtf"

}  // namespace runner
}  // namespace robottestingframework
