#include "runner/model/suite_model.h"

#include <algorithm>
#include <cctype>

namespace robottestingframework {
namespace runner {

std::string SourceLocation::toString() const {
    if (line == 0) {
        return file;
    }
    return file + ":" + std::to_string(line);
}

bool isPoolItemId(const std::string& id) {
    return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
}

}  // namespace runner
}  // namespace robottestingframework
