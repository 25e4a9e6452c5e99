#include "runner/cli/last_run_cache.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <system_error>

#include "runner/cli/program_name.h"
#include "runner/history/collected_run.h"

namespace robottestingframework {
namespace runner {

const char* const lastFailedFileName = "lastfailed";

namespace {

namespace fs = std::filesystem;

bool failing(const std::string& state) {
    return state == "failed" || state == "error" || state == "crashed" || state == "timed out";
}

const char* const readme =
    "# robottestingframework-testrunner cache folder\n"
    "\n"
    "This folder keeps the last run's failed tests (one test id a line in `lastfailed`), for\n"
    "the runner's `--lf` (`--last-failed`) and `--ff` (`--failed-first`).\n"
    "\n"
    "**Do not** commit it to version control (its `.gitignore` says so). `--cache-dir DIR` moves\n"
    "it, `--no-cache` turns it off.\n";

bool writeFile(const fs::path& path, const std::string& text, std::string& error) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
        error = "cannot write " + path.string() + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

}  // namespace

bool readLastFailed(const std::string& folder, std::set<std::string>& ids, std::string& error) {
    const fs::path path = fs::path(folder) / lastFailedFileName;
    std::error_code code;
    if (!fs::exists(path, code)) {
        return true;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot read " + path.string() + ": " + std::strerror(errno);
        return false;
    }
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        if (!line.empty()) {
            ids.insert(line);
        }
    }
    return true;
}

std::set<std::string> updatedLastFailed(
    const std::set<std::string>& previous,
    const std::vector<std::pair<std::string, std::string>>& results) {
    std::set<std::string> ids = previous;
    for (const auto& result : results) {
        if (failing(result.second)) {
            ids.insert(result.first);
        } else if (result.second != "interrupted") {
            ids.erase(result.first);
        }
    }
    return ids;
}

bool writeLastFailed(const std::string& folder, const std::set<std::string>& ids,
                     std::string& error) {
    const fs::path dir(folder);
    std::error_code code;
    if (!fs::is_directory(dir, code)) {
        fs::create_directories(dir, code);
        if (code) {
            error = "cannot make the cache folder " + folder + ": " + code.message();
            return false;
        }
        if (!writeFile(
                dir / ".gitignore",
                "# Made by robottestingframework-testrunner: nothing here is to commit.\n*\n",
                error) ||
            !writeFile(dir / "README.md", readme, error)) {
            return false;
        }
    }
    std::string text;
    for (const auto& id : ids) {
        if (id.find('\n') == std::string::npos) {
            text += id + "\n";
        }
    }
    // Written whole beside it (a name of its own per process), then renamed over it: a reader sees
    // the old file or the new one.
    const fs::path target = dir / lastFailedFileName;
    const fs::path temporary =
        dir / (std::string(lastFailedFileName) + ".tmp-" + std::to_string(std::random_device{}()));
    if (!writeFile(temporary, text, error)) {
        fs::remove(temporary, code);
        return false;
    }
    fs::rename(temporary, target, code);
    if (code) {
        error = "cannot write " + target.string() + ": " + code.message();
        fs::remove(temporary, code);
        return false;
    }
    return true;
}

void recordLastRun(const Options& options, const TestResultCollector& collector,
                   std::FILE* console) {
    if (options.noCache) {
        return;
    }
    // Whether any test failed, before any id is made: a run that passes in a folder without a
    // cache leaves none behind, and builds no list of ids (at the end of the run, that list
    // would be the run's peak memory: 10 000 ids).
    bool failed = false;
    std::size_t count = 0;
    for (const SuiteRecord& suite : collector.suites()) {
        for (const TestRecord& test : suite.tests) {
            failed = failed || failing(toString(test.status));
            ++count;
        }
    }
    std::error_code code;
    if (!failed && !fs::is_directory(options.cacheDir, code)) {
        return;
    }
    std::vector<std::pair<std::string, std::string>> results;
    results.reserve(count);
    for (const SuiteRecord& suite : collector.suites()) {
        for (const TestRecord& test : suite.tests) {
            results.emplace_back(historyTestId(suite, test), toString(test.status));
        }
    }
    std::set<std::string> previous;
    std::string error;
    if (!readLastFailed(options.cacheDir, previous, error) ||
        !writeLastFailed(options.cacheDir, updatedLastFailed(previous, results), error)) {
        std::fprintf(console, "%s: warning: %s (--cache-dir, --no-cache)\n", programName,
                     error.c_str());
    }
}

}  // namespace runner
}  // namespace robottestingframework
