#pragma once
// The blocks' angles read once a step. An adapter's state() (for the run monitor), rocking() and fill() (for a sample)
// all read the same bodies after a step, and in ODE, Bullet and DART an angle is atan2 of the body's rotation, the
// hooks' costliest call (callgrind: four a step on a free vibration sampled every step). The second read returns the
// first's value, bit for bit what reading it again would give; the step forgets them. Engine-free.
#include <cmath>
#include <limits>

namespace vssw::multibody {

class StepAngles {
public:
    // The bodies moved (a step): the next read of each angle reads the body.
    void forget() { lower_ = upper_ = kUnread; }
    // The lower (upper) block's angle: read() the first time since forget(), then the same value.
    template <class Read>
    double lower(Read read) {
        if (std::isnan(lower_)) lower_ = read();
        return lower_;
    }
    template <class Read>
    double upper(Read read) {
        if (std::isnan(upper_)) upper_ = read();
        return upper_;
    }

private:
    static constexpr double kUnread = std::numeric_limits<double>::quiet_NaN();
    double lower_ = kUnread, upper_ = kUnread;
};

}  // namespace vssw::multibody
