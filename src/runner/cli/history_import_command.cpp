#include "runner/cli/history_import_command.h"

#include <sys/stat.h>

#include <cstdio>
#include <stdexcept>

#include "runner/cli/exit_status.h"
#include "runner/cli/program_name.h"
#include "runner/history/history_database.h"
#include "runner/history/run_appender.h"
#include "runner/reports/imported_report.h"

namespace robottestingframework {
namespace runner {

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
            run.runKey = "import:" + path + "@" + std::to_string(run.started);
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
