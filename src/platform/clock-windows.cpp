// Windows: the performance counter, which is monotonic and does not follow the wall clock.
#include "platform/clock.h"

#include <windows.h>

namespace robottestingframework {
namespace platform {

double monotonicSeconds() {
    static const double ticksPerSecond = [] {
        LARGE_INTEGER frequency{};
        ::QueryPerformanceFrequency(&frequency);
        return static_cast<double>(frequency.QuadPart);
    }();
    LARGE_INTEGER now{};
    ::QueryPerformanceCounter(&now);
    return static_cast<double>(now.QuadPart) / ticksPerSecond;
}

}  // namespace platform
}  // namespace robottestingframework
