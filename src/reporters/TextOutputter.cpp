// RTF 2.x's TextOutputter, kept for programs that use it: the text reporter under its old name.
#include <robottestingframework/TextOutputter.h>

#include "reporters/atomic_file.h"
#include "reporters/text_reporter.h"

namespace robottestingframework {

TextOutputter::TextOutputter(TestResultCollector& collector, bool verbose)
    : collector_(collector), verbose_(verbose) {}

std::string TextOutputter::text(bool summary) const {
    reporters::ReporterSettings settings;
    settings.passedChecks = verbose_;
    settings.reports = verbose_;
    settings.summary = summary;
    return reporters::TextReporter(collector_, settings).document();
}

bool TextOutputter::write(std::string filename, bool summary, TestMessage* error) {
    return reporters::writeReport(filename, text(summary), error);
}

}  // namespace robottestingframework
