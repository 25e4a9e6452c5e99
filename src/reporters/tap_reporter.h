// The TAP version 14 output (https://testanything.org/tap-version-14-specification.html): each
// suite a subtest, a test point per test, YAML diagnostics for failures, "# SKIP" with the
// reason, and "Bail out!" when a suite's fixture failed.
#pragma once

#include <cstdint>
#include <vector>

#include <robottestingframework/ResultEvent.h>

#include "reporters/nested_text.h"
#include "reporters/reporter.h"

namespace robottestingframework {
namespace reporters {

class TapReporter : public StreamingReporter {
public:
    // The collector's clock times the messages.
    TapReporter(const TestResultCollector& collector, ReporterSettings settings)
        : collector_(collector), settings_(settings) {}
    void writeDocument(ReportText& out) override;

    // Reads the record: a message or a problem (the table's columns) goes to its test's point;
    // the frames, output, retries, measurements and attachments go to the handlers below.
    void onEvent(const RunEvent& event) override;
    void startTestSuite(const TestSuite* suite) override;
    void endTestSuite(const TestSuite* suite) override;
    void startTest(const Test* test) override;
    void endTest(const Test* test) override;
    void addOutput(const Test* test, const std::string& text) override;
    void renameTest(const Test* test, const std::string& name) override;
    void retryTest(const Test* test, TestMessage msg) override;
    void addMeasurement(const Test* test, const Measurement& measurement, bool passed) override;
    void addAttachment(const Test* test, const Attachment& attachment) override;

private:
    // A suite being written: its test points so far (unindented; indented when it closes).
    struct Block {
        std::string name;
        NestedText body;
        std::size_t points = 0;
        bool failed = false;
        std::vector<TestMessage> fixtureProblems;
        std::string attachments;  // its fixtures' (YAML list items), with its point
    };
    // A test between its start and end, found by its id, not by order, pointer or name.
    struct OpenTest {
        std::uint64_t id;
        std::string name;
        TestStatus status = TestStatus::Passed;
        TestMessage reason;  // the first message of the state it has now
        std::string output;
        std::size_t retries = 0;  // earlier failed attempts (--retries)
        // Its reports and checks, each a YAML list item's text ("[time] kind: text" quoted, or
        // with diagnostics a map of that `text` and its `diagnostics`; messageItem).
        std::vector<std::string> messages;
        // How many measurements it gave: the collector keeps them, and the file is written
        // from its records (issue 22: 10 000 tests held their YAML until the end).
        std::size_t measurements = 0;
        // The YAML list items of its attachments, written with its point.
        std::string attachments;
    };
    OpenTest* openTest(const Test* test);
    // The point last written, so that a retry can take it back: one point per test.
    struct LastPoint {
        std::uint64_t id = 0;  // the test's id; 0 for none
        std::size_t depth = 0;
        std::size_t bodySize = 0;
        std::size_t points = 0;
        bool failed = false;
        std::size_t retries = 0;
    };
    LastPoint last_;
    std::uint64_t retrying_ = 0;  // the id of the test whose next start is a retry; 0 for none
    std::size_t retryCount_ = 0;

    void note(const Test* test, const ResultEvent& event);
    static void closeTest(std::vector<Block>& blocks, const OpenTest& test);
    static void closeSuite(std::vector<Block>& blocks, std::vector<std::string>& bailOuts);

    const TestResultCollector& collector_;
    ReporterSettings settings_;
    std::vector<Block> blocks_{Block{}};  // the top level first, the innermost suite last
    std::vector<OpenTest> open_;
    std::vector<std::string> bailOuts_;
};

}  // namespace reporters
}  // namespace robottestingframework
