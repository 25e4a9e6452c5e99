// The HTML report's page, built into the library from src/reporters/html_page/: the skeleton
// (with @REPORT_CSS@, @REPORT_DATA@ and @REPORT_JS@ where the rest goes), its script and style.
#pragma once

#include <string>

namespace robottestingframework {
namespace reporters {

const std::string& htmlReportPage();
const std::string& htmlReportScript();
const std::string& htmlReportStyle();

}  // namespace reporters
}  // namespace robottestingframework
