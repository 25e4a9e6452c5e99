#include "platform/clock.h"

#include <cmath>

namespace robottestingframework {
namespace platform {

Deadline::Deadline(double seconds) : at_(seconds > 0 ? monotonicSeconds() + seconds : -1) {}

bool Deadline::expired() const {
    return at_ >= 0 && monotonicSeconds() >= at_;
}

int Deadline::remainingMs(int cap) const {
    if (at_ < 0) {
        return cap;
    }
    double left = (at_ - monotonicSeconds()) * 1000.0;
    int ms = left <= 0 ? 0 : static_cast<int>(std::ceil(left));
    return cap >= 0 && ms > cap ? cap : ms;
}

}  // namespace platform
}  // namespace robottestingframework
