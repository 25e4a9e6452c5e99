#include "reporters/reporter_registry.h"

#include "reporters/html_reporter.h"
#include "reporters/json_reporter.h"
#include "reporters/junit_reporter.h"
#include "reporters/tap_reporter.h"
#include "reporters/text_reporter.h"

namespace robottestingframework {
namespace reporters {

namespace {

template <typename Format>
std::unique_ptr<Reporter> make(const TestResultCollector& collector,
                               const ReporterSettings& settings) {
    return std::make_unique<Format>(collector, settings);
}

}  // namespace

const std::vector<ReporterType>& reporterTypes() {
    // One row per format.
    // clang-format off
    static const std::vector<ReporterType> types = {
        {"text", "result.txt", make<TextReporter>},
        {"junit", "result.xml", make<JUnitReporter>},
        {"tap", "result.tap", make<TapReporter>},
        {"json", "result.json", make<JsonReporter>},
        {"html", "result.html", make<HtmlReporter>},
    };
    // clang-format on
    return types;
}

const ReporterType* findReporterType(const std::string& name) {
    for (const ReporterType& type : reporterTypes()) {
        if (type.name == name) {
            return &type;
        }
    }
    return nullptr;
}

std::string reporterTypeList() {
    const auto& types = reporterTypes();
    std::string list;
    for (std::size_t i = 0; i < types.size(); ++i) {
        if (i > 0) {
            list += i + 1 == types.size() ? " or " : ", ";
        }
        list += types[i].name;
    }
    return list;
}

}  // namespace reporters
}  // namespace robottestingframework
