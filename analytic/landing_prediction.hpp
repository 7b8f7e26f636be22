#pragma once
// The landing (theta1 = 0) of a flight predicted before it is reached, so that a step can be aimed at it
// (simulate.cpp): by the parabola through theta1, theta1', theta1'' anywhere, and from the last two free flights in a
// free vibration.
#include <algorithm>
#include <cmath>
#include <limits>

namespace vssw {

// An event placed within this of a step's end is carried there by y + dh f(y), whose error (dh^2/2 |y''|, < 1e-16
// here) is far below the integration error, instead of by another step.
inline constexpr double kTaylorSpan = 1e-8;  // [s]
// A free flight's duration is predicted from the last two (FlightHistory) and aimed at only when the first- and
// second-order predictions agree within this: on Fig. 6 the second-order error was a tenth of their difference, so
// the aimed step lands within kTaylorSpan. A prediction that misses costs a step, never accuracy.
inline constexpr double kFlightPredictionAgreement = 10.0 * kTaylorSpan;  // [s]
// No landing ahead.
inline constexpr double kNoLanding = std::numeric_limits<double>::infinity();

// Time to the landing, u = side theta1 = 0 coming down, along u + u' d + u'' d^2 / 2 from u >= 0 (or u < 0 just past
// it, moving down: then negative, the landing behind), in forms without cancellation; infinity when the parabola
// does not come down to zero (it turns first, or rises for ever).
inline double parabola_landing(double u, double u_dot, double u_ddot) {
    const double disc = u_dot * u_dot - 2.0 * u_ddot * u;
    if (!(disc >= 0.0)) return kNoLanding;
    if (u_dot < 0.0) return 2.0 * u / (-u_dot + std::sqrt(disc));  // moving down: the first root
    if (u_ddot < 0.0) return (u_dot + std::sqrt(disc)) / -u_ddot;    // rising: down again after the turn
    return kNoLanding;
}

// Durations and launch speeds of the last two free flights (from theta1 = 0, the ground at rest). In the limit of
// small flights the duration is proportional to the launch speed (2|v|/a); the ratio duration/speed drifts slowly
// with the amplitude, and its drift from one flight to the next predicts the next one.
struct FlightHistory {
    double duration[2] = {0.0, 0.0}, speed[2] = {0.0, 0.0};  // [1]: the latest
    int known = 0;

    void add(double t, double v) {
        duration[0] = duration[1];
        speed[0] = speed[1];
        duration[1] = t;
        speed[1] = v;
        known = std::min(known + 1, 2);
    }
    // The next flight's duration from its launch speed, or infinity when the two predictions disagree.
    double predict(double v) const {
        if (known < 2) return kNoLanding;
        const double first = duration[1] * v / speed[1];
        const double second = first * (duration[1] / speed[1]) / (duration[0] / speed[0]);
        return std::abs(second - first) < kFlightPredictionAgreement ? second : kNoLanding;
    }
};

}  // namespace vssw
