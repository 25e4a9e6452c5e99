#include "runner/cli/suite_durations.h"

#include <filesystem>
#include <stdexcept>

#include "runner/history/history_database.h"
#include "runner/history/history_error.h"
#include "runner/history/history_queries.h"
#include "runner/reports/report_reader.h"

namespace robottestingframework {
namespace runner {

SuiteSeconds suiteDurations(const std::string& file) {
    // A history file is looked at by its first bytes only when it can be read again: a pipe
    // (`--durations-from <(cat report.xml)`) is read once, as the report it must then be.
    std::error_code failed;
    const bool regular = std::filesystem::is_regular_file(file, failed);
    if (regular && looksLikeHistoryFile(file)) {
        try {
            HistoryDatabase database(file, HistoryDatabase::Mode::Read);
            return latestSuiteSeconds(database);
        } catch (const HistoryError& e) {
            // Its message names the file as --history does: say which option gave it.
            const std::string what = e.what();
            const std::string prefix = "--history ";
            throw std::runtime_error("--durations-from " + (what.rfind(prefix, 0) == 0
                                                                ? what.substr(prefix.size())
                                                                : what));
        }
    }
    SuiteSeconds seconds;
    for (const auto& suite : readReport("--durations-from", file).suites) {
        seconds[suite.name] = suite.seconds;
    }
    return seconds;
}

}  // namespace runner
}  // namespace robottestingframework
