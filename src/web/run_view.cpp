#include "web/run_view.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include <robottestingframework/ResultEvent.h>

#include "core/text_safety.h"

namespace robottestingframework {
namespace web {

namespace {

using Json = nlohmann::json;

// What a test printed and its messages are capped: the page is for reading, not for archiving
// (the result files keep everything), and each change re-sends the test's messages. Without a
// cap a test that failed a check 4 000 times made the runner hold 3 GB and take 3 minutes. The
// first messages of each kind are kept (the first failure decides); the rest are only counted.
// Messages keep their first 4 KiB.
const std::size_t maxOutput = 64 * 1024;
const std::size_t maxMessages = 200;
const std::size_t maxMessageText = 4 * 1024;
// The log of /update (RTF 2.x): its last 1 MiB, cut when it reaches 2 MiB.
const std::size_t maxLog = 1024 * 1024;

bool keep(RunView::Message message, std::vector<RunView::Message>& messages, std::size_t& hidden) {
    // Reports and the rest (failures, errors, ...) each have their own cap: a failure after
    // thousands of reports is still shown.
    const bool report = message.kind == "report";
    const auto alike = std::count_if(messages.begin(), messages.end(), [&](const auto& kept) {
        return (kept.kind == "report") == report;
    });
    if (static_cast<std::size_t>(alike) >= maxMessages) {
        ++hidden;
        return false;
    }
    if (message.text.size() > maxMessageText) {
        const std::size_t cut = reporters::characterBoundary(message.text, maxMessageText);
        message.text = message.text.substr(0, cut) + " [... cut on this page; the result " +
                       "files have all of it]";
    }
    messages.push_back(std::move(message));
    return true;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Test output may hold anything; invalid UTF-8 becomes U+FFFD instead of an exception.
std::string dump(const Json& json) {
    return json.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// RTF 2.x's /status codes.
int statusCode(const std::string& state) {
    if (state == "running") {
        return 1;
    }
    if (state == "passed") {
        return 3;
    }
    if (state == "not run" || state == "skipped") {
        return 0;
    }
    return 2;
}

}  // namespace

RunView::RunView(bool verbose) : verbose_(verbose) {}

double RunView::clock() const {
    return secondsSince(origin_);
}

RunView::SuiteView& RunView::openSuite() {
    if (openSuite_ == none) {
        // Tests run outside any suite get one of their own.
        SuiteView loose;
        loose.name = "(no suite)";
        loose.started = std::chrono::steady_clock::now();
        loose.startedAt = clock();
        suites_.push_back(std::move(loose));
        openSuite_ = suites_.size() - 1;
        publishSuite(openSuite_);
    }
    return suites_[openSuite_];
}

void RunView::startRun() {
    std::lock_guard<std::mutex> lock(mutex_);
    runState_ = "running";
    runStarted_ = std::chrono::steady_clock::now();
    log("run started");
    publishRun();
}

void RunView::endRun() {
    std::lock_guard<std::mutex> lock(mutex_);
    runState_ = "finished";
    runDuration_ = secondsSince(runStarted_);
    if (openSuite_ != none && openSuites_.empty()) {
        SuiteView& loose = suites_[openSuite_];
        loose.state = loose.failed ? "failed" : "passed";
        loose.duration = secondsSince(loose.started);
        publishSuite(openSuite_);
        openSuite_ = none;
    }
    log("run finished: " + std::to_string(counts_[0]) + " passed, " + std::to_string(counts_[1]) +
        " failed, " + std::to_string(counts_[2]) + " skipped");
    publishRun();
}

RunView::TestView RunView::plannedTest(const std::string& suite, const Planned& test) const {
    TestView view;
    view.id = test.id;
    view.name = test.name;
    const auto history = history_.find(suite.empty() ? test.name : suite + "/" + test.name);
    if (history != history_.end()) {
        view.history = history->second;
    }
    return view;
}

void RunView::setPlan(const std::vector<PlannedSuite>& suites) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const PlannedSuite& planned : suites) {
        SuiteView suite;
        suite.name = planned.name;
        suite.state = "waiting";
        for (const Planned& test : planned.tests) {
            suite.tests.push_back(plannedTest(planned.name, test));
        }
        suites_.push_back(std::move(suite));
        publishSuite(suites_.size() - 1);
    }
    publishRun();
}

void RunView::startSuite(const std::string& name, const std::vector<Planned>& tests,
                         std::uint64_t id) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (runState_ == "waiting") {
        // A suite run on its own, without a runner.
        runState_ = "running";
        runStarted_ = std::chrono::steady_clock::now();
    }
    // The planned suite of this name, when the plan named it and it has not started yet.
    std::size_t index = none;
    for (std::size_t i = 0; i < suites_.size() && index == none; ++i) {
        if (suites_[i].state == "waiting" && suites_[i].name == name) {
            index = i;
        }
    }
    if (index == none) {
        suites_.emplace_back();
        index = suites_.size() - 1;
    }
    SuiteView& suite = suites_[index];
    suite.name = name;
    suite.id = id;
    suite.state = "running";
    suite.started = std::chrono::steady_clock::now();
    suite.startedAt = clock();
    for (const auto& test : tests) {
        const bool known = std::any_of(suite.tests.begin(), suite.tests.end(),
                                       [&](const TestView& kept) { return kept.id == test.id; });
        if (!known) {
            suite.tests.push_back(plannedTest(name, test));
        }
    }
    openSuites_.push_back(index);
    openSuite_ = index;
    log("suite " + name + " started");
    publishSuite(openSuite_);
    publishRun();
}

void RunView::setTestHistory(const std::string& testId, const std::string& json) {
    std::lock_guard<std::mutex> lock(mutex_);
    history_[testId] = json;
}

void RunView::endSuite(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (openSuites_.empty()) {
        return;
    }
    // Suites run side by side (-j N) end in any order: the latest open one of that name.
    std::size_t at = openSuites_.size() - 1;
    for (std::size_t i = openSuites_.size(); i > 0 && !name.empty(); --i) {
        if (suites_[openSuites_[i - 1]].name == name) {
            at = i - 1;
            break;
        }
    }
    const bool innermost = at + 1 == openSuites_.size();
    const std::size_t index = openSuites_[at];
    openSuites_.erase(openSuites_.begin() + static_cast<std::ptrdiff_t>(at));
    SuiteView& suite = suites_[index];
    suite.state = suite.failed ? "failed" : "passed";
    suite.duration = secondsSince(suite.started);
    openSuite_ = openSuites_.empty() ? none : openSuites_.back();
    if (innermost && openSuite_ != none && suite.failed) {
        suites_[openSuite_].failed = true;  // a nested suite's failure is its parent's
    }
    log("suite " + suite.name + " " + suite.state);
    publishSuite(index);
    publishRun();
}

std::optional<RunView::Place> RunView::findOpen(std::uint64_t id) const {
    for (auto it = openTests_.rbegin(); it != openTests_.rend(); ++it) {
        if (it->id == id) {
            return it->place;
        }
    }
    return std::nullopt;
}

void RunView::startTest(std::uint64_t id, const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    // Its place among the planned tests of the open suites: with -j N several are open, and
    // their events come interleaved.
    std::size_t index = none;
    std::size_t suiteIndex = none;
    for (auto open = openSuites_.rbegin(); open != openSuites_.rend() && index == none; ++open) {
        const std::vector<TestView>& tests = suites_[*open].tests;
        for (std::size_t i = 0; i < tests.size(); ++i) {
            if (tests[i].id == id && tests[i].state == "not run") {
                index = i;
                suiteIndex = *open;
                break;
            }
        }
    }
    if (index == none) {
        openSuite();
        suiteIndex = openSuite_;
    }
    SuiteView& suite = suites_[suiteIndex];
    if (index == none) {
        // Not planned (a repetition, or a suite that did not list it).
        TestView view;
        view.id = id;
        suite.tests.push_back(std::move(view));
        index = suite.tests.size() - 1;
    }
    TestView& test = suite.tests[index];
    test.name = name;
    test.state = "running";
    test.started = std::chrono::steady_clock::now();
    test.startedAt = clock();
    openTests_.push_back({id, {suiteIndex, index}});
    log("test " + name + " started");
    publishTest(suiteIndex, index);
}

void RunView::endTest(std::uint64_t id) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::optional<Place> place = findOpen(id);
    if (!place) {
        return;
    }
    for (std::size_t i = openTests_.size(); i > 0; --i) {
        if (openTests_[i - 1].id == id) {
            openTests_.erase(openTests_.begin() + static_cast<std::ptrdiff_t>(i - 1));
            break;
        }
    }
    TestView& test = testAt(*place);
    test.state = test.retries > 0 && test.worst == TestStatus::Passed ? toString(TestStatus::Flaky)
                                                                      : toString(test.worst);
    test.duration = secondsSince(test.started);
    ended_ = {id, place->suite, place->test};
    if (test.worst == TestStatus::Passed) {
        ++counts_[0];
    } else if (test.worst == TestStatus::Skipped) {
        ++counts_[2];
    } else {
        ++counts_[1];
        suites_[place->suite].failed = true;
    }
    log("test " + test.name + " " + test.state);
    publishTest(place->suite, place->test);
    publishRun();
}

void RunView::renameTest(std::uint64_t id, const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::optional<Place> place = findOpen(id);
    if (!place) {
        return;
    }
    TestView& test = testAt(*place);
    log("test " + test.name + " renamed " + name);
    test.name = name;
    publishTest(place->suite, place->test);
}

void RunView::retryTest(std::uint64_t id) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (ended_.id == 0 || ended_.id != id || ended_.suite >= suites_.size() ||
        ended_.test >= suites_[ended_.suite].tests.size() ||
        suites_[ended_.suite].tests[ended_.test].id != id) {
        return;
    }
    SuiteView& suite = suites_[ended_.suite];
    TestView& test = suite.tests[ended_.test];
    // The failed attempt no longer counts; its messages stay, to show what happened.
    if (isFailure(test.worst) && counts_[1] > 0) {
        --counts_[1];
        suite.failed = false;
        for (const TestView& other : suite.tests) {
            suite.failed = suite.failed || (&other != &test && other.state != "not run" &&
                                            other.state != "running" && other.state != "passed" &&
                                            other.state != "skipped" && other.state != "flaky");
        }
    }
    test.worst = TestStatus::Passed;
    test.repetition.clear();
    test.state = "not run";  // its next startTest finds it again
    ++test.retries;
    ended_ = Ended();
}

void RunView::startRepetition(std::uint64_t id, unsigned int index, unsigned int count) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (const std::optional<Place> place = findOpen(id)) {
            testAt(*place).repetition = repetitionId(id, index);
        }
    }
    addMessage(id, "report", repetitionMessage(index, count), TestStatus::Passed);
}

void RunView::addMessage(std::uint64_t id, const char* kind, const TestMessage& msg,
                         TestStatus status) {
    std::lock_guard<std::mutex> lock(mutex_);
    Message message;
    message.kind = kind;
    message.text = msg.getMessage();
    if (!msg.getDetail().empty()) {
        message.text += message.text.empty() ? msg.getDetail() : ": " + msg.getDetail();
    }
    message.diagnostics = msg.getDiagnostics().empty() ? "" : msg.diagnosticsText();
    if (!msg.getSourceFileName().empty()) {
        message.where = msg.getSourceFileName();
        if (msg.getSourceLineNumber() > 0) {
            message.where += ":" + std::to_string(msg.getSourceLineNumber());
        }
    }
    log("[" + message.kind + "] " + message.text);
    const std::optional<Place> place = findOpen(id);
    if (!place) {
        // A suite's own (its fixture's): the open suite of that id, else the innermost.
        std::size_t index = none;
        for (auto open = openSuites_.rbegin(); open != openSuites_.rend() && id != 0; ++open) {
            if (suites_[*open].id == id) {
                index = *open;
                break;
            }
        }
        if (index == none) {
            openSuite();
            index = openSuite_;
        }
        SuiteView& suite = suites_[index];
        if (isFailure(status)) {
            suite.failed = true;
        }
        if (keep(message, suite.messages, suite.hiddenReports)) {
            publishSuite(index);
        }
        return;
    }
    TestView& test = testAt(*place);
    if (status > test.worst) {
        test.worst = status;
    }
    message.repetition = test.repetition;
    // A failed check is followed by the failure it makes, with the same words: said once, as
    // the failure (as the console and the reports say it).
    if (status == TestStatus::Failed && !test.messages.empty() &&
        test.messages.back().kind == "check failed" && test.messages.back().text == message.text &&
        test.messages.back().where == message.where &&
        test.messages.back().repetition == message.repetition) {
        test.messages.back().kind = message.kind;
        publishTest(place->suite, place->test);
        return;
    }
    if (keep(message, test.messages, test.hiddenReports)) {
        publishTest(place->suite, place->test);
    }
}

void RunView::addOutput(std::uint64_t id, const std::string& text) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::optional<Place> place = verbose_ ? findOpen(id) : std::nullopt;
    if (!place) {
        return;
    }
    TestView& test = testAt(*place);
    if (test.output.size() >= maxOutput) {
        return;
    }
    test.output += text.substr(0, maxOutput - test.output.size());
    if (test.output.size() >= maxOutput) {
        test.output += "\n[output cut at 64 KiB]\n";
    }
    publishTest(place->suite, place->test);
}

void RunView::addMeasurement(std::uint64_t id, MeasurementView measurement) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::optional<Place> place = findOpen(id);
    if (!place) {
        return;
    }
    TestView& test = testAt(*place);
    // Capped as messages are: each change re-sends the test.
    if (test.measurements.size() < maxMessages) {
        test.measurements.push_back(std::move(measurement));
        publishTest(place->suite, place->test);
    }
}

void RunView::close() {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    changed_.notify_all();
}

void RunView::addAttachment(std::uint64_t id, AttachmentView attachment) {
    // The run's attachments folder bounds their bytes; this bounds the page's list.
    constexpr std::size_t maxAttachments = 10000;
    std::lock_guard<std::mutex> lock(mutex_);
    if (const std::optional<Place> place = findOpen(id)) {
        attachment.test = testAt(*place).name;
    } else if (openSuite_ != none && attachment.test.empty()) {
        attachment.test = suites_[openSuite_].name;  // a fixture's (a process's log)
    }
    log("[attachment] " + attachment.test + ": " + attachment.name);
    if (attachments_.size() < maxAttachments) {
        attachments_.push_back(std::move(attachment));
    }
}

bool RunView::attachment(std::size_t index, AttachmentView& found) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (index >= attachments_.size()) {
        return false;
    }
    found = attachments_[index];
    return true;
}

std::string RunView::runJson() const {
    std::size_t planned = 0;
    for (const auto& suite : suites_) {
        planned += suite.tests.size();
    }
    Json run = {{"state", runState_},
                {"tests", planned},
                {"passed", counts_[0]},
                {"failed", counts_[1]},
                {"skipped", counts_[2]},
                {"duration", runState_ == "finished"  ? runDuration_
                             : runState_ == "running" ? secondsSince(runStarted_)
                                                      : 0.0}};
    if (runState_ == "finished" && !attachments_.empty()) {
        // Links at the end: a file is complete once its test has ended, and the list is
        // sent once instead of with every change.
        Json list = Json::array();
        for (std::size_t i = 0; i < attachments_.size(); ++i) {
            const AttachmentView& attachment = attachments_[i];
            list.push_back({{"test", attachment.test},
                            {"name", attachment.name},
                            {"description", attachment.description},
                            {"url", "/attachments/" + std::to_string(i)}});
        }
        run["attachments"] = std::move(list);
    }
    return dump(run);
}

namespace {

Json toJson(const std::vector<RunView::Message>& messages) {
    Json list = Json::array();
    for (const auto& message : messages) {
        Json item = {{"kind", message.kind}, {"text", message.text}, {"where", message.where}};
        if (!message.repetition.empty()) {
            item["repetition"] = message.repetition;
        }
        if (!message.diagnostics.empty()) {
            item["diagnostics"] = message.diagnostics;
        }
        list.push_back(std::move(item));
    }
    return list;
}

// A test as the page reads it. One that runs several times says which repetition it is in; one
// that runs once is shown as it always was.
Json toJson(const RunView::TestView& test) {
    Json json = {{"id", test.id},
                 {"name", test.name},
                 {"state", test.state},
                 {"duration", test.duration},
                 {"startedAt", test.startedAt},
                 {"messages", toJson(test.messages)},
                 {"hiddenReports", test.hiddenReports},
                 {"output", test.output}};
    if (!test.repetition.empty()) {
        json["repetition"] = test.repetition;
    }
    if (!test.history.empty()) {
        json["history"] = Json::parse(test.history, nullptr, false);
    }
    if (!test.measurements.empty()) {
        Json list = Json::array();
        for (const auto& measured : test.measurements) {
            Json item = {{"name", measured.name},
                         {"value", measured.value},
                         {"unit", measured.unit},
                         {"passed", measured.passed}};
            if (measured.low) {
                item["low"] = *measured.low;
            }
            if (measured.high) {
                item["high"] = *measured.high;
            }
            list.push_back(std::move(item));
        }
        json["measurements"] = std::move(list);
    }
    return json;
}

}  // namespace

void RunView::publishRun() {
    publish("run", "{\"type\":\"run\",\"run\":" + runJson() + "}");
}

void RunView::publishSuite(std::size_t index) {
    const SuiteView& suite = suites_[index];
    Json json = {{"type", "suite"},
                 {"index", index},
                 {"suite",
                  {{"name", suite.name},
                   {"state", suite.state},
                   {"duration", suite.duration},
                   {"startedAt", suite.startedAt},
                   {"messages", toJson(suite.messages)},
                   {"hiddenReports", suite.hiddenReports},
                   {"tests", Json::array()}}}};
    for (const auto& test : suite.tests) {
        json["suite"]["tests"].push_back(toJson(test));
    }
    publish("s" + std::to_string(index), dump(json));
}

void RunView::publishTest(std::size_t suiteIndex, std::size_t index) {
    const TestView& test = suites_[suiteIndex].tests[index];
    Json json = {{"type", "test"}, {"suite", suiteIndex}, {"index", index}, {"test", toJson(test)}};
    publish("t" + std::to_string(suiteIndex) + "." + std::to_string(index), dump(json));
}

namespace {

Json worldJson(const std::string& name, const std::string& users, const std::string& state,
               double startedAt, double readyAt, double stoppedAt, const std::string& reason) {
    return {{"name", name},           {"users", users},     {"state", state},
            {"startedAt", startedAt}, {"readyAt", readyAt}, {"stoppedAt", stoppedAt},
            {"reason", reason}};
}

}  // namespace

void RunView::worldPhase(const std::string& name, const std::string& phase,
                         const std::string& detail) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::size_t index = none;
    for (std::size_t i = worlds_.size(); i > 0 && index == none; --i) {
        if (worlds_[i - 1].name == name && worlds_[i - 1].stoppedAt < 0) {
            index = i - 1;
        }
    }
    if (index == none || phase == "start") {
        worlds_.emplace_back();
        index = worlds_.size() - 1;
        worlds_[index].name = name;
        worlds_[index].startedAt = clock();
    }
    WorldView& world = worlds_[index];
    if (phase == "start") {
        world.users = detail;
    } else if (phase == "ready") {
        world.readyAt = clock();
        world.state = "ready";
    } else if (phase == "stop") {
        world.stoppedAt = clock();
        world.state = world.state == "collapsed" ? "collapsed" : "stopped";
        if (!detail.empty()) {
            world.reason += (world.reason.empty() ? "" : "; ") + detail;
        }
    } else {
        world.state = phase;
        world.reason = detail;
        if (phase == "failed") {
            world.stoppedAt = clock();
        }
    }
    publishWorld(index);
}

void RunView::publishWorld(std::size_t index) {
    const WorldView& w = worlds_[index];
    Json json = {{"type", "world"},
                 {"index", index},
                 {"world", worldJson(w.name, w.users, w.state, w.startedAt, w.readyAt, w.stoppedAt,
                                     w.reason)}};
    publish("w" + std::to_string(index), dump(json));
}

void RunView::publish(const std::string& key, std::string json) {
    std::uint64_t& latest = latest_[key];
    changes_.erase(latest);  // 0 (none) is no change
    latest = ++lastChange_;
    changes_.emplace(latest, std::move(json));
    changed_.notify_all();
}

void RunView::log(const std::string& line) {
    log_ += line.size() > maxMessageText ? line.substr(0, maxMessageText) + " [...]" : line;
    log_ += '\n';
    if (log_.size() > 2 * maxLog) {
        const std::size_t from = log_.find('\n', log_.size() - maxLog);
        log_ = "[... earlier lines dropped]\n" +
               log_.substr(from == std::string::npos ? log_.size() - maxLog : from + 1);
    }
}

std::string RunView::snapshotJson() const {
    std::lock_guard<std::mutex> lock(mutex_);
    Json suites = Json::array();
    for (const auto& suite : suites_) {
        Json tests = Json::array();
        for (const auto& test : suite.tests) {
            tests.push_back(toJson(test));
        }
        suites.push_back({{"name", suite.name},
                          {"state", suite.state},
                          {"duration", suite.duration},
                          {"startedAt", suite.startedAt},
                          {"messages", toJson(suite.messages)},
                          {"hiddenReports", suite.hiddenReports},
                          {"tests", std::move(tests)}});
    }
    Json worlds = Json::array();
    for (const auto& w : worlds_) {
        worlds.push_back(
            worldJson(w.name, w.users, w.state, w.startedAt, w.readyAt, w.stoppedAt, w.reason));
    }
    Json snapshot = {{"seq", lastChange_},
                     {"now", clock()},
                     {"run", Json::parse(runJson())},
                     {"worlds", std::move(worlds)},
                     {"suites", std::move(suites)}};
    return dump(snapshot);
}

std::string RunView::statusJson() const {
    std::lock_guard<std::mutex> lock(mutex_);
    Json status = {{"name", ""}, {"testStatus", Json::array()}};
    std::size_t shown = openSuite_ != none ? openSuite_ : suites_.size() - 1;
    if (shown < suites_.size()) {
        status["name"] = suites_[shown].name;
        for (const auto& test : suites_[shown].tests) {
            status["testStatus"].push_back(statusCode(test.state));
        }
    }
    return dump(status);
}

std::string RunView::logText() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return reporters::escapeMarkup(log_, reporters::Markup::Quoted);
}

std::uint64_t RunView::waitForChanges(std::uint64_t since, std::chrono::milliseconds timeout,
                                      std::string& out, bool& closed) const {
    std::unique_lock<std::mutex> lock(mutex_);
    if (since > lastChange_) {
        since = 0;  // a number from another run (the page outlived its runner): all again
    }
    changed_.wait_for(lock, timeout, [&] { return closed_ || lastChange_ > since; });
    closed = closed_;
    // A change replaced by a later one of the same thing is not sent: the later one says all.
    // Each says the view's clock as it is sent, which the page ticks running tests by.
    const std::string now = ",\"now\":" + Json(clock()).dump() + ",";
    for (auto it = changes_.upper_bound(since); it != changes_.end(); ++it) {
        out += "id: " + std::to_string(it->first) +
               "\ndata: {\"seq\":" + std::to_string(it->first) + now + it->second.substr(1) +
               "\n\n";
    }
    return lastChange_;
}

}  // namespace web
}  // namespace robottestingframework
