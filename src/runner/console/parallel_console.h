// The console of a run of several suites at once (-j N): one line per test as it ends, from
// whichever suite, never two mixed; the messages of a test that did not pass under its line;
// the lines the scheduler has to say (a suite waiting for a lock); on a terminal, the progress
// line at the bottom (progress_line.h), fed by the live events. The summary comes at the end, from
// the ordered results.
#pragma once

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestStatus.h>

#include "runner/console/progress_line.h"
#include "runner/schedule/scheduler.h"

namespace robottestingframework {
namespace runner {

struct ParallelConsoleSettings {
    bool verbose = false;              // reports and output too
    bool colours = false;              // status words in colour
    bool summary = true;               // the summary at the end
    ProgressLine* progress = nullptr;  // the stream is a terminal: the line at the bottom
    unsigned int retries = 0;          // --retries: a failed attempt with retries left is a RETRY
};

class ParallelConsole : public SchedulerView, public TestListener {
public:
    // `collector`: the run's, fed the ordered events before this console (for the summary).
    ParallelConsole(std::FILE* stream, const TestResultCollector& collector,
                    ParallelConsoleSettings settings);

    void events(const TestSuite& suite, const std::vector<SuiteEvents::Event>& events) override;
    void note(const std::string& line) override;

    // On the ordered stream: only the end of the run matters here.
    void endTestRunner() override;

private:
    class Live;
    // A test that started and has not ended yet (of any suite).
    struct Open {
        TestStatus status = TestStatus::Passed;
        std::vector<std::string> lines;  // its messages, shown under its line
        double started = 0;         // when it started (steady seconds), as the collector times it
        unsigned int attempts = 0;  // earlier attempts (--retries)
        std::string name;           // the name it gave itself, once it renamed itself
    };
    void line(const std::string& text);

    std::map<const Test*, Open> open_;
    std::FILE* stream_;
    const TestResultCollector& collector_;
    ParallelConsoleSettings settings_;
};

}  // namespace runner
}  // namespace robottestingframework
