// Decides, just before each test, that it must not run: --fail-fast after a failure, or a
// depends="..." on a test that did not pass. Such a test is reported skipped with the reason.
#pragma once

#include <deque>
#include <mutex>
#include <string>
#include <vector>

#include <robottestingframework/TestGate.h>
#include <robottestingframework/TestListener.h>

#include "runner/model/stand_in_test.h"
#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

// Whether depends="`dependency`" names `spec`: its name="...", or its plug-in as written, with
// or without folder, lib prefix and suffix.
bool dependencyNames(const std::string& dependency, const TestSpec& spec);

// Empty when every depends="..." of `suites` names a test of the run (its name="..." or its
// plug-in as written, with or without folder, lib prefix and suffix); else
// "suite.xml:12: unknown dependency 'x' ...". The name a test reports is only known once it
// ran, so it cannot make a dependency known here.
std::string findUnknownDependency(const std::vector<SuiteSpec>& suites);

// Empty when the dependencies have no cycle (each test of one would be skipped for the other,
// and the run would look green); else "suite.xml:3: dependency cycle: a (suite.xml:3) depends
// on b (suite.xml:4), which depends on a (suite.xml:3)", or "... depends on itself".
std::string findDependencyCycle(const std::vector<SuiteSpec>& suites);

// Also a listener: any failure reported during the run (a test's or a fixture's) trips
// --fail-fast.
class RunGate : public TestGate, public TestListener {
public:
    // `tests`: every stand-in of the run, in order; must outlive the gate.
    explicit RunGate(const std::deque<PluginTest>& tests) : tests_(tests) {}

    void setFailFast(bool on) { failFast_ = on; }

    bool skip(const Test* test, TestMessage& reason) override;

    // Reads the record: a kind that trips --fail-fast (the table's column) trips the gate; a
    // test run again (--retries) has not failed yet: only its last attempt counts. The others,
    // most of a run's events (starts, ends, checks), pass by.
    void onEvent(const RunEvent& event) override;

private:
    void tripped(const Test* test);
    void retried(const Test* test);

    const std::deque<PluginTest>& tests_;
    bool failFast_ = false;
    std::mutex mutex_;          // a test's helper threads may report too
    std::string firstFailure_;  // empty until something failed
    const Test* firstFailing_ = nullptr;
};

}  // namespace runner
}  // namespace robottestingframework
