// Fuzz target: --merge over shard reports (cmake/Fuzz.cmake, ./run.sh fuzz). The input is up to
// four reports separated by a line "--8<--"; the first byte picks the output format (bit 2 set:
// JUnit, else JSON) and --expect-shards (its two low bits): 'f' JUnit of 2 shards, 'd' JUnit,
// 'b' JSON of 2 shards, '`' JSON. Each report goes through the shared reader as
// --merge reads it, then the merge runs over those that were read. Every error names a report;
// a merged document is itself a report the reader takes back (--durations and --rerun-failed
// read merged reports too).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "runner/reports/merge_reports.h"
#include "runner/reports/report_reader.h"

using namespace robottestingframework;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    runner::MergeRequest request;
    request.type = (data[0] & 4u) != 0 ? "junit" : "json";
    request.file = "merged";
    request.expectShards = data[0] & 3u;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    const std::string cut = "\n--8<--\n";
    std::vector<runner::Report> reports;
    std::size_t begin = 0;
    while (reports.size() < 4) {
        const std::size_t end = text.find(cut, begin);
        const std::string path = "shard" + std::to_string(reports.size());
        try {
            reports.push_back(runner::parseReport(
                "--merge", text.substr(begin, end == std::string::npos ? end : end - begin), path));
        } catch (const std::runtime_error& e) {
            if (std::string(e.what()).find(path) == std::string::npos) {
                __builtin_trap();  // every error names the report
            }
            return 0;
        }
        if (end == std::string::npos) {
            break;
        }
        begin = end + cut.size();
    }
    std::string merged;
    try {
        merged = runner::mergeReports(request, std::move(reports));
    } catch (const std::runtime_error& e) {
        if (std::string(e.what()).rfind("--merge ", 0) != 0 ||
            std::string(e.what()).find("shard") == std::string::npos) {
            __builtin_trap();  // every error is the option's and names a report or a shard
        }
        return 0;
    }
    try {
        runner::parseReport("--durations", merged, "merged");
    } catch (const std::runtime_error&) {
        __builtin_trap();  // the merge wrote what the runner cannot read back
    }
    return 0;
}
