#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

std::string SourceLocation::toString() const {
    if (line == 0) {
        return file;
    }
    return file + ":" + std::to_string(line);
}

}  // namespace runner
}  // namespace robottestingframework
