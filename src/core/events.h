// Events by name: what sends an event of a kind (TestResult's named senders, the collector, the
// executors, the worker, the scheduler) makes it here. Defined beside the table of kinds
// (TestStatus.cpp), so that a kind is spelled in the table, here, and in RTF 2.x's adapter
// (TestListener::onEvent) only: a new kind adds its row, and a maker if something sends it.
// Each returns the event with its kind and what the maker names set; the rest is ResultEvent's
// defaults (no test, time 0).
#pragma once

#include <memory>
#include <string>

#include <robottestingframework/Attachment.h>
#include <robottestingframework/Measurement.h>
#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestMessage.h>

namespace robottestingframework {
namespace events {

ResultEvent startRunner();
ResultEvent endRunner();
ResultEvent startSuite();
ResultEvent endSuite();
ResultEvent startTest();
ResultEvent endTest();
ResultEvent report(TestMessage msg);
ResultEvent check(TestMessage msg, bool passed);
ResultEvent failure(TestMessage msg);
ResultEvent error(TestMessage msg);
ResultEvent skipped(TestMessage reason);
ResultEvent crash(TestMessage msg);
ResultEvent timeout(TestMessage msg);
ResultEvent interrupted(TestMessage msg);
// What the test printed.
ResultEvent output(const std::string& text);
// The test now goes by `name`.
ResultEvent rename(const std::string& name);
ResultEvent retry(TestMessage msg);
// Repetition `index` of `count` of the test starts.
ResultEvent repetition(unsigned int index, unsigned int count);
// `measured` (null: the event without its data), within its limits or not; `described` its
// message (describeMeasurement's, or empty when nothing keeps it).
ResultEvent measurement(std::shared_ptr<const Measurement> measured, bool passed,
                        TestMessage described);
ResultEvent attachment(std::shared_ptr<const Attachment> attached, TestMessage described);
// A shared world's phase ("start", "ready", ...) and its detail, about no test.
ResultEvent world(const std::string& name, const std::string& phase, const std::string& detail);

}  // namespace events
}  // namespace robottestingframework
