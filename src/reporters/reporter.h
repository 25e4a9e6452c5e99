// The one interface every output format stands on. A reporter hears the run's events (it is a
// TestListener) and, at the end, writes its whole file front to back. Two bases, as Catch2 has
// them: StreamingReporter builds its text as events arrive (TAP); CumulativeReporter writes from
// the collector's finished records (text, JUnit, JSON, HTML).
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResultCollector.h>

#include "reporters/history_strip.h"

namespace robottestingframework {
namespace reporters {

// What the plan says of a test that its events do not: the HTML report shows it.
struct TestFacts {
    std::string type;    // "dll", "python", ...; empty: from the file
    std::string plugin;  // as the suite wrote it
    std::string param;   // expanded
    std::vector<std::string> tags;
};

// What the command line says about every output.
struct ReporterSettings {
    // The runner's reports keep everything whatever -v/-d say (those change only the console).
    // RTF 2.x's outputters keep these only when made verbose: passed checks (JUnitOutputter,
    // TextOutputter), reports and what tests printed (TextOutputter).
    bool passedChecks = true;
    bool reports = true;
    bool summary = true;  // --no-summary turns it off (text only)
    // The shard this run is (--shard-index/--shard-count or a CI engine's variables): JUnit
    // and JSON say so, for --merge --expect-shards to check.
    bool sharded = false;
    unsigned int shardIndex = 0;
    unsigned int shardCount = 0;
    std::string shardPlan;  // the whole run's plan (planIdentity): --merge checks it is one run
    bool rerun = false;     // --rerun-failed: --merge lets it replace the tests it reruns
    // The place (from 0) of each suite of this run among every selected suite, before a shard
    // was taken: JUnit's testsuite id and JSON's testId, so merged shards order their suites
    // as one machine would. Empty: the suites' places in this run.
    std::vector<std::size_t> suitePlaces;
    // What the run was, as "name: value" pairs in order (command line, variables, host,
    // version, isolation, jobs): the HTML report's run metadata. Empty outside the runner.
    std::vector<std::pair<std::string, std::string>> runFacts;
    // Each planned test's facts by its whole id ("SUITE/id"). Empty outside the runner.
    std::map<std::string, TestFacts> testFacts;
    std::size_t suitePlace(std::size_t index) const {
        return suitePlaces.empty() ? index : suitePlaces[index % suitePlaces.size()];
    }
    // --history: each test's recent runs, filled once this run is in the history (before the
    // outputs are written); null without --history.
    std::shared_ptr<const HistoryStrips> history;
};

// A report's text as a reporter writes it, front to back: kept whole (Reporter::document()), or
// handed on to its file a block at a time (Reporter::write()), so that the runner never holds a
// whole report of 10 000 tests (several MiB, more with measurements) beside its records.
class ReportText {
public:
    virtual ~ReportText() = default;
    ReportText& operator+=(std::string_view text) {
        if (text_.size() + text.size() < handOnAt_) {
            text_.append(text.data(), text.size());
        } else {
            handOn(text);
        }
        return *this;
    }
    ReportText& operator+=(char c) { return *this += std::string_view(&c, 1); }

protected:
    explicit ReportText(std::size_t handOnAt) : handOnAt_(handOnAt) {}
    // Passes on text_, then `more` (not copied into text_ when it is long), and empties text_.
    virtual void handOn(std::string_view more) = 0;

    std::string text_;

private:
    std::size_t handOnAt_;
};

// All of a report's text, kept in one string.
class WholeReportText : public ReportText {
public:
    WholeReportText() : ReportText(static_cast<std::size_t>(-1)) {}
    std::string take() { return std::move(text_); }

protected:
    void handOn(std::string_view more) override { text_.append(more.data(), more.size()); }
};

class Reporter : public TestListener {
public:
    // Writes the file's whole content, as things stand, into `out`. Called once the run is
    // over, or cut short (then with what is known: tests still open show as interrupted).
    virtual void writeDocument(ReportText& out) = 0;
    // The file's whole content in one string.
    std::string document();
    // Writes the document whole or not at all, a block at a time; on failure false, with
    // `error` naming the file.
    bool write(const std::string& filename, TestMessage* error);
};

// Reacts to each event; events say which test they are about, so nothing is inferred from order.
class StreamingReporter : public Reporter {};

// Ignores events: the collector (a listener of the same run) keeps the records it writes from.
class CumulativeReporter : public Reporter {
public:
    CumulativeReporter(const TestResultCollector& collector, ReporterSettings settings)
        : collector_(collector), settings_(settings) {}

protected:
    const TestResultCollector& collector_;
    ReporterSettings settings_;
};

}  // namespace reporters
}  // namespace robottestingframework
