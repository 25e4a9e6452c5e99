// The one interface every output format stands on. A reporter hears the run's events (it is a
// TestListener) and, at the end, gives its whole file. Two bases, as Catch2 has them:
// StreamingReporter builds its text as events arrive (TAP); CumulativeReporter writes from the
// collector's finished records (text, JUnit, JSON, HTML).
#pragma once

#include <string>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResultCollector.h>

namespace robottestingframework {
namespace reporters {

// What the command line says about every output.
struct ReporterSettings {
    bool verbose = false;  // --verbose: reports, checks and output in full
    bool summary = true;   // --no-summary turns it off (text only)
};

class Reporter : public TestListener {
public:
    // The file's whole content as things stand. Called once the run is over, or cut short (then
    // with what is known: tests still open show as interrupted).
    virtual std::string document() = 0;
    // Writes document() whole or not at all; on failure false, with `error` naming the file.
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
