// Monotonic time and deadlines: timeouts must not jump when someone sets the wall clock.
#pragma once

namespace robottestingframework {
namespace platform {

// Seconds since an arbitrary fixed point; never goes backwards.
double monotonicSeconds();

// A point in time `seconds` from now; 0 (or less) means never.
class Deadline {
public:
    explicit Deadline(double seconds = 0);
    bool never() const { return at_ < 0; }
    bool expired() const;
    // Milliseconds left, rounded up, at most `cap`; -1 (wait forever) when never, unless capped.
    int remainingMs(int cap = -1) const;

private:
    double at_;
};

}  // namespace platform
}  // namespace robottestingframework
