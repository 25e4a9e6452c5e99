// RTF_web's live page: a RunView filled by the run's events and served by a WebServer.
#include <cstdint>
#include <string>
#include <vector>

#include <robottestingframework/TestSuite.h>

#include "web/live_page.h"
#include "web/run_view.h"
#include "web/web_server.h"

namespace robottestingframework {
namespace web {

namespace {

// The view is filled by the run's events and read by the server; tests are found by the ids
// the events carry.
class ServedLivePage : public LivePage {
public:
    ServedLivePage(const std::string& host, unsigned int port, bool verbose)
        : view(verbose), server(view) {
        listening = server.start(host, port, failure);
    }
    ~ServedLivePage() override {
        view.close();  // ends the event streams first, so stop() does not wait for them
        server.stop();
    }

    bool isListening() const override { return listening; }
    std::string error() const override { return failure; }
    unsigned int port() const override { return listening ? server.port() : 0; }
    void setTestHistory(const std::string& testId, const std::string& json) override {
        view.setTestHistory(testId, json);
    }
    void setPlan(const std::vector<const TestSuite*>& suites) override {
        std::vector<RunView::PlannedSuite> planned;
        for (const TestSuite* suite : suites) {
            if (suite != nullptr) {
                planned.push_back({suite->getName(), plannedTests(suite)});
            }
        }
        view.setPlan(planned);
    }

    // Reads the record: a message or a problem (the table's columns) is shown under its test
    // as it comes; the frames, output, retries, repetitions, measurements, attachments and
    // worlds go to the handlers below.
    void onEvent(const RunEvent& event) override;
    void startTest(const Test* test) override;
    void endTest(const Test* test) override;
    void renameTest(const Test* test, const std::string& name) override;
    void startTestSuite(const TestSuite* suite) override;
    void endTestSuite(const TestSuite* suite) override;
    void startTestSuite(const Test* suite) override;
    void endTestSuite(const Test* suite) override;
    void startTestRunner() override;
    void endTestRunner() override;
    void addOutput(const Test* test, const std::string& text) override;
    void retryTest(const Test* test, TestMessage msg) override;
    void startRepetition(const Test* test, unsigned int index, unsigned int count) override;
    void addEvent(const Test* test, const ResultEvent& event) override;
    void addMeasurement(const Test* test, const Measurement& measurement, bool passed) override;
    void addAttachment(const Test* test, const Attachment& attachment) override;

private:
    static std::vector<RunView::Planned> plannedTests(const TestSuite* suite) {
        std::vector<RunView::Planned> tests;
        for (const Test* test : suite->tests()) {
            tests.push_back({test->getId(), shownAs(test, test->getName())});
        }
        return tests;
    }
    static std::uint64_t idOf(const Test* test) { return test != nullptr ? test->getId() : 0; }
    // "tests/arith.lua (ArmTest)": the test's id in its suite and the name it gives itself
    // (docs/reference/test-ids.md), as the console shows it.
    static std::string shownAs(const Test* test, const std::string& name) {
        const std::string& key = test->getKey();
        // An absolute path is a loader's default name, not one the test chose.
        if (key.empty() || key == name || name.empty() || name[0] == '/') {
            return key.empty() ? name : key;
        }
        return key + " (" + name + ")";
    }

    RunView view;
    WebServer server;
    std::string failure;
    bool listening = false;
};

}  // namespace

void ServedLivePage::onEvent(const RunEvent& event) {
    const ResultEvent& data = event.data;
    // Passing checks are many and say little; a failed one is shown with its failure.
    if (isSaid(data) || (isMessage(data.kind) && !isHiddenCheck(data))) {
        view.addMessage(idOf(event.test), nameOf(data.kind, data.passed), data.message,
                        stateOf(data.kind));
        return;
    }
    TestListener::onEvent(event);
}

void ServedLivePage::addEvent(const Test* /*test*/, const ResultEvent& event) {
    if (isWorldPhase(event.kind)) {
        view.worldPhase(event.testName, event.message.getMessage(), event.message.getDetail());
    }
}

void ServedLivePage::addMeasurement(const Test* test, const Measurement& measurement, bool passed) {
    // Shown as it comes; one outside its limits is followed by the failure that says so.
    view.addMessage(idOf(test), passed ? "measurement" : "measurement outside limits",
                    TestMessage(describeMeasurement(measurement)), TestStatus::Passed);
    view.addMeasurement(idOf(test), {measurement.name, measurement.value, measurement.unit,
                                     measurement.low, measurement.high, passed});
}

void ServedLivePage::addAttachment(const Test* test, const Attachment& attachment) {
    RunView::AttachmentView shown;
    shown.name = attachment.originalName;
    shown.description = attachment.description;
    shown.absolutePath = attachment.absolutePath;
    shown.contentType = attachment.contentType();
    view.addAttachment(idOf(test), std::move(shown));
}

void ServedLivePage::addOutput(const Test* test, const std::string& text) {
    view.addOutput(idOf(test), text);
}

void ServedLivePage::retryTest(const Test* test, TestMessage /*msg*/) {
    view.retryTest(idOf(test));
}

void ServedLivePage::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    view.startRepetition(idOf(test), index, count);
}

void ServedLivePage::startTest(const Test* test) {
    view.startTest(idOf(test), test != nullptr ? shownAs(test, test->getName()) : std::string());
}

void ServedLivePage::endTest(const Test* test) {
    view.endTest(idOf(test));
}

void ServedLivePage::renameTest(const Test* test, const std::string& name) {
    view.renameTest(idOf(test), test != nullptr ? shownAs(test, name) : name);
}

void ServedLivePage::startTestSuite(const TestSuite* suite) {
    if (suite == nullptr) {
        view.startSuite(std::string(), {});
        return;
    }
    view.startSuite(suite->getName(), plannedTests(suite), suite->getId());
}

void ServedLivePage::endTestSuite(const TestSuite* suite) {
    endTestSuite(static_cast<const Test*>(suite));
}

void ServedLivePage::startTestSuite(const Test* suite) {
    // A suite known only as a Test: its tests are learnt as they start.
    view.startSuite(suite != nullptr ? suite->getName() : std::string(), {},
                    suite != nullptr ? suite->getId() : 0);
}

void ServedLivePage::endTestSuite(const Test* suite) {
    view.endSuite(suite != nullptr ? suite->getName() : std::string());
}

void ServedLivePage::startTestRunner() {
    view.startRun();
}

void ServedLivePage::endTestRunner() {
    view.endRun();
}

}  // namespace web
}  // namespace robottestingframework

// Found by name (live_page.h) by RTF's WebProgressListener.
extern "C" __attribute__((visibility("default"))) robottestingframework::web::LivePage*
robottestingframework_web_open_live_page(const char* host, unsigned int port, bool verbose) {
    return new robottestingframework::web::ServedLivePage(host, port, verbose);
}
