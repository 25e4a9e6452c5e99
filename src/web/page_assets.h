// The page's files, built into the library from src/web/page/ (no files to install or find).
#pragma once

#include <string>

namespace robottestingframework {
namespace web {

const std::string& pageHtml();
const std::string& pageJs();
const std::string& pageCss();

}  // namespace web
}  // namespace robottestingframework
