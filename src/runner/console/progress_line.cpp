#include "runner/console/progress_line.h"

#include <algorithm>
#include <cmath>

#include <robottestingframework/TestSuite.h>

#include "core/text_safety.h"
#include "platform/terminal_width.h"
#include "reporters/summary.h"

namespace robottestingframework {
namespace runner {

namespace {

using Clock = std::chrono::steady_clock;
const char* const eraseLine = "\r\033[K";

double secondsBetween(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
}

// "4.2 s", "1:05", "1:02:03".
std::string duration(double seconds, bool tenths) {
    char text[32];
    if (tenths && seconds < 60) {
        std::snprintf(text, sizeof(text), "%.1f s", seconds);
        return text;
    }
    const long whole = std::lround(seconds);
    if (whole < 3600) {
        std::snprintf(text, sizeof(text), "%ld:%02ld", whole / 60, whole % 60);
    } else {
        std::snprintf(text, sizeof(text), "%ld:%02ld:%02ld", whole / 3600, (whole / 60) % 60,
                      whole % 60);
    }
    return text;
}

// The terminal's width; 80 when it cannot be told.
std::size_t widthOf(std::FILE* stream) {
    return platform::terminalWidth(stream, 80);
}

}  // namespace

ProgressLine::ProgressLine(std::FILE* stream, ProgressSettings settings)
    : stream_(stream), settings_(std::move(settings)) {
    if (settings_.redrawMilliseconds > 0) {
        ticker_ = std::thread([this] { tick(); });
    }
}

ProgressLine::~ProgressLine() {
    {
        std::lock_guard<std::mutex> lock(tickMutex_);
        stopping_ = true;
    }
    tickWake_.notify_all();
    if (ticker_.joinable()) {
        ticker_.join();
    }
    finish();
}

// A test that runs for seconds still shows its time going up.
void ProgressLine::tick() {
    for (;;) {
        {
            std::unique_lock<std::mutex> lock(tickMutex_);
            if (tickWake_.wait_for(lock, std::chrono::milliseconds(settings_.redrawMilliseconds),
                                   [this] { return stopping_; })) {
                return;
            }
        }
        std::lock_guard<std::recursive_mutex> drawing(mutex_);
        if (paused_ == 0 && active_ && !running_.empty()) {
            draw();
        }
    }
}

void ProgressLine::pause() {
    mutex_.lock();
    if (paused_++ == 0 && shown_) {
        std::fputs(eraseLine, stream_);
        shown_ = false;
    }
}

void ProgressLine::resume() {
    if (--paused_ == 0 && active_) {
        draw();
    }
    mutex_.unlock();
}

void ProgressLine::finish() {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    if (shown_) {
        std::fputs(eraseLine, stream_);
        std::fflush(stream_);
        shown_ = false;
    }
    active_ = false;
}

void ProgressLine::restart() {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    started_ = failed_ = 0;
    seen_.clear();
    counted_.clear();
    running_.clear();
    order_.clear();
    suitesRunning_.clear();
    suitesEnded_.clear();
    active_ = true;
}

void ProgressLine::suiteStarted(const std::string& suite) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    suitesRunning_.emplace(suite, Clock::now());
}

void ProgressLine::suiteEnded(const std::string& suite) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    auto found = suitesRunning_.find(suite);
    if (found != suitesRunning_.end()) {
        suitesRunning_.erase(found);
    }
    ++suitesEnded_[suite];
}

void ProgressLine::testStarted(const Test* test, const std::string& suite,
                               const std::string& name) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    if (seen_.insert(test).second) {
        ++started_;
    }
    running_[test] = Running{suite, name, Clock::now(), false};
    order_.erase(std::remove(order_.begin(), order_.end(), test), order_.end());
    order_.push_back(test);
}

void ProgressLine::testRenamed(const Test* test, const std::string& name) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    auto found = running_.find(test);
    if (found != running_.end()) {
        found->second.name = name;
    }
}

void ProgressLine::testFailed(const Test* test) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    auto found = running_.find(test);
    if (found != running_.end()) {
        found->second.failed = true;
    }
}

void ProgressLine::testEnded(const Test* test) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    auto found = running_.find(test);
    if (found == running_.end()) {
        return;
    }
    if (found->second.failed && counted_.insert(test).second) {
        ++failed_;
    }
    running_.erase(found);
    order_.erase(std::remove(order_.begin(), order_.end(), test), order_.end());
}

void ProgressLine::testRetried(const Test* test) {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    if (counted_.erase(test) != 0) {
        --failed_;
    }
}

std::string ProgressLine::eta(Clock::time_point now) const {
    double known = 0;
    unsigned int knownCount = 0;
    for (const auto& suite : settings_.suites) {
        if (suite.second >= 0) {
            known += suite.second;
            ++knownCount;
        }
    }
    if (knownCount == 0) {
        return {};
    }
    // An unknown suite counts as the mean of the known ones.
    const double mean = known / knownCount;
    auto expected = [&](const std::string& name) {
        for (const auto& suite : settings_.suites) {
            if (suite.first == name) {
                return suite.second >= 0 ? suite.second : mean;
            }
        }
        return mean;
    };
    double left = 0;
    std::size_t suitesLeft = 0;
    std::map<std::string, unsigned int> ended = suitesEnded_;
    for (const auto& suite : settings_.suites) {
        auto done = ended.find(suite.first);
        if (done != ended.end() && done->second > 0) {
            --done->second;
            continue;
        }
        left += suite.second >= 0 ? suite.second : mean;
        ++suitesLeft;
    }
    for (const auto& running : suitesRunning_) {
        left -= std::min(secondsBetween(running.second, now), expected(running.first));
    }
    if (suitesLeft == 0) {
        return {};
    }
    const double lanes = std::min<double>(settings_.jobs, static_cast<double>(suitesLeft));
    return "ETA " + duration(std::max(0.0, left) / std::max(1.0, lanes), false);
}

std::string ProgressLine::text() {
    std::lock_guard<std::recursive_mutex> lock(mutex_);
    const Clock::time_point now = Clock::now();
    // A record the plan did not know (a world process's failed stop) counts in N too.
    const std::size_t total = std::max<std::size_t>(started_, settings_.tests);
    std::string line = "[" + std::to_string(started_) + "/" + std::to_string(total) + "]";
    if (!order_.empty()) {
        const Running& latest = running_.at(order_.back());
        line += " " + latest.suite + " :: " + latest.name + " (" +
                duration(secondsBetween(latest.started, now), true) + ")";
        if (order_.size() > 1) {
            line += " +" + std::to_string(order_.size() - 1) + " running";
        }
    }
    std::string tail;
    if (failed_ > 0) {
        tail += ", " + std::to_string(failed_) + " failed";
    }
    const std::string left = eta(now);
    if (!left.empty()) {
        tail += ", " + left;
    }
    // Never wider than the terminal: a wrapped line cannot be rewritten in place. The name
    // gives way first.
    const std::size_t width = widthOf(stream_) - 1;
    if (line.size() + tail.size() > width) {
        const std::size_t room = width > tail.size() + 3 ? width - tail.size() - 3 : 0;
        line = line.substr(0, room) + "...";
    }
    if (settings_.colours && failed_ > 0) {
        const std::size_t at = tail.find(" failed");
        const std::size_t start = 2;  // after ", "
        tail = tail.substr(0, start) + reporters::colour::red + tail.substr(start, at + 7 - start) +
               reporters::colour::plain + tail.substr(at + 7);
    }
    return line + tail;
}

// Starts at the line's beginning: after a pause's erase or a console line's newline there is
// nothing to erase.
void ProgressLine::draw() {
    const std::string line = text();
    if (shown_) {
        std::fputs(eraseLine, stream_);
    }
    std::fputs(line.c_str(), stream_);
    std::fflush(stream_);
    shown_ = true;
}

void ProgressLine::Before::onEvent(const RunEvent& event) {
    line_.pause();
    TestListener::onEvent(event);  // the named handlers below follow the run
}

void ProgressLine::After::onEvent(const RunEvent& /*event*/) {
    line_.resume();
}

void ProgressLine::Before::startTestSuite(const TestSuite* suite) {
    if (suite != nullptr) {
        suite_ = reporters::visibleText(suite->getName());
        line_.suiteStarted(suite_);
    }
}
void ProgressLine::Before::endTestSuite(const TestSuite* suite) {
    if (suite != nullptr) {
        line_.suiteEnded(reporters::visibleText(suite->getName()));
    }
}
void ProgressLine::Before::startTest(const Test* test) {
    line_.testStarted(test, suite_,
                      test != nullptr ? reporters::shownAs(test->getKey(), test->getName()) : "");
}
void ProgressLine::Before::endTest(const Test* test) {
    line_.testEnded(test);
}
void ProgressLine::Before::renameTest(const Test* test, const std::string& name) {
    line_.testRenamed(test, test != nullptr ? reporters::shownAs(test->getKey(), name) : name);
}
void ProgressLine::Before::retryTest(const Test* test, TestMessage /*msg*/) {
    line_.testRetried(test);
}
void ProgressLine::Before::addFailure(const Test* test, TestMessage /*msg*/) {
    line_.testFailed(test);
}
void ProgressLine::Before::addError(const Test* test, TestMessage /*msg*/) {
    line_.testFailed(test);
}
void ProgressLine::Before::addCrash(const Test* test, TestMessage /*msg*/) {
    line_.testFailed(test);
}
void ProgressLine::Before::addTimeout(const Test* test, TestMessage /*msg*/) {
    line_.testFailed(test);
}
void ProgressLine::Before::addInterrupted(const Test* test, TestMessage /*msg*/) {
    line_.testFailed(test);
}
void ProgressLine::Before::addCheck(const Test* test, TestMessage /*msg*/, bool passed) {
    if (!passed) {
        line_.testFailed(test);
    }
}
void ProgressLine::Before::addEvent(const Test* test, const ResultEvent& event) {
    if (isFailure(stateOf(event.kind))) {
        line_.testFailed(test);
    }
}
void ProgressLine::Before::startTestRunner() {
    line_.restart();
}
void ProgressLine::Before::endTestRunner() {
    line_.finish();
}

}  // namespace runner
}  // namespace robottestingframework
