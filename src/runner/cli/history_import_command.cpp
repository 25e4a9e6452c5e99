#include "runner/cli/history_import_command.h"

#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <stdexcept>

#include "runner/cli/exit_status.h"
#include "runner/cli/program_name.h"
#include "runner/history/history_database.h"
#include "runner/history/history_queries.h"
#include "runner/history/run_appender.h"
#include "runner/reports/imported_report.h"

namespace robottestingframework {
namespace runner {

namespace {

// How far after now a report's time may be: a day covers any time zone a timestamp without
// one was written in, and a clock a little ahead.
constexpr double futureToleranceSeconds = 24 * 3600;

// "2026-11-27T10:00:00Z".
std::string isoUtc(double seconds) {
    const std::time_t when = static_cast<std::time_t>(seconds);
    char text[64] = "?";
    // std::gmtime, not gmtime_r (which MinGW-w64 declares only when asked): the import runs on
    // the main thread alone.
    if (const std::tm* parts = std::gmtime(&when)) {
        std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", parts);
    }
    return text;
}

}  // namespace

int historyImportCommand(const Options& options) {
    try {
        HistoryDatabase database(options.history, HistoryDatabase::Mode::Append);
        for (const std::string& path : options.historyImports) {
            const ImportedReport report = readImportedReport(path);
            HistoryRun run;
            run.started = report.started;
            if (run.started < 0) {  // the report does not say: when it was written
                struct stat status {};
                run.started =
                    ::stat(path.c_str(), &status) == 0 ? static_cast<double>(status.st_mtime) : 0;
            }
            const double now =
                std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
                    .count();
            if (run.started > now + futureToleranceSeconds) {
                // It would stay "the newest run" of the history forever.
                throw std::runtime_error("--history-import " + path + ": its time, " +
                                         isoUtc(run.started) + ", is in the future (now is " +
                                         isoUtc(now) + "); fix the report's timestamp");
            }
            // Known by its content, not its path: the same report imported again (by any
            // path) adds nothing. Imports of earlier versions were keyed by path and time.
            run.runKey = "import:" + report.digest;
            const std::string earlierKey = "import:" + path + "@" + std::to_string(run.started);
            if (hasRun(database, run.runKey) || hasRun(database, earlierKey)) {
                std::printf("%s: %s: already in %s, not loaded again\n", programName, path.c_str(),
                            options.history.c_str());
                continue;
            }
            run.source = path;
            RunAppender appender(database, run);
            for (const ReportedSuite& suite : report.suites) {
                appender.addSuite({suite.name, suite.seconds});
            }
            for (const ReportedTest& test : report.tests) {
                appender.addTest({test.suite.empty() ? test.name : test.suite + "/" + test.name,
                                  test.suite, test.state, test.seconds, test.attempts});
            }
            appender.commit();
            std::printf("%s: %s: %zu tests loaded into %s\n", programName, path.c_str(),
                        report.tests.size(), options.history.c_str());
        }
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "%s: %s\n", programName, e.what());
        return configurationError;
    }
    return allPassed;
}

}  // namespace runner
}  // namespace robottestingframework
