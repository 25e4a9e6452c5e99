// RTF 2.x's JUnitOutputter, kept for programs that use it: the JUnit reporter under its old name.
#include <robottestingframework/JUnitOutputter.h>

#include "reporters/atomic_file.h"
#include "reporters/junit_reporter.h"

namespace robottestingframework {

JUnitOutputter::JUnitOutputter(TestResultCollector& collector, bool verbose)
    : collector_(collector), verbose_(verbose) {}

std::string JUnitOutputter::xml() const {
    reporters::ReporterSettings settings;
    settings.passedChecks = verbose_;
    return reporters::JUnitReporter(collector_, settings).document();
}

bool JUnitOutputter::write(std::string filename, TestMessage* error) {
    return reporters::writeReport(filename, xml(), error);
}

}  // namespace robottestingframework
