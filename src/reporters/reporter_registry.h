// The one table of output formats: name -> factory. The command line (its checks, its help, its
// errors) and the runner read it; adding a format is a file pair and a row here.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "reporters/reporter.h"

namespace robottestingframework {
namespace reporters {

struct ReporterType {
    std::string name;         // as in --output NAME:FILE
    std::string defaultFile;  // written when no --output names a file
    std::function<std::unique_ptr<Reporter>(const TestResultCollector&, const ReporterSettings&)>
        make;
};

// In the order --help lists them.
const std::vector<ReporterType>& reporterTypes();
// nullptr when no format has that name.
const ReporterType* findReporterType(const std::string& name);
// "text, junit, tap, json or html".
std::string reporterTypeList();

}  // namespace reporters
}  // namespace robottestingframework
