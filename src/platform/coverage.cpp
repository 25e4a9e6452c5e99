#include "platform/coverage.h"

#ifdef RTF_COVERAGE
// libgcov's, linked in by --coverage: writes the counters so far to the .gcda files.
extern "C" void __gcov_dump(void);
#endif

namespace robottestingframework {
namespace platform {

void flushCoverage() {
#ifdef RTF_COVERAGE
    __gcov_dump();
#endif
}

bool coverageBuild() {
#ifdef RTF_COVERAGE
    return true;
#else
    return false;
#endif
}

}  // namespace platform
}  // namespace robottestingframework
