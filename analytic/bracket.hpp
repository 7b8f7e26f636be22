#pragma once
// Root bracketing shared by the event-driven phases (simulate.cpp, off_roller.cpp).

namespace vssw {

constexpr int kMaxBisections = 400;  // bound on root-search iterations; reached only by a broken bracket

// Shrinks a bracket [lo, hi] of a sign change of f (f(lo) on one side, f(hi) on the other or zero) to width tol by
// Illinois false position, bisecting whenever two steps have not halved it: superlinear on the smooth functions met
// here, never slower than bisection. hi keeps the side of f(hi).
template <class F>
void shrink_bracket(F f, double& lo, double& hi, double tol) {
    double flo = f(lo), fhi = f(hi);
    int retained = 0;      // which end the last two steps kept: -1 lo, +1 hi (Illinois halves its value)
    int slow_steps = 0;    // steps since the bracket last halved
    double mark = hi - lo;
    for (int i = 0; i < kMaxBisections && hi - lo > tol; ++i) {
        double x = 0.5 * (lo + hi);
        if (slow_steps < 2 && fhi != flo) {
            const double secant = (lo * fhi - hi * flo) / (fhi - flo);
            if (secant > lo && secant < hi) x = secant;
        }
        const double fx = f(x);
        if (fx != 0.0 && (fx > 0.0) == (flo > 0.0)) {
            lo = x;
            flo = fx;
            if (retained == 1) fhi *= 0.5;
            retained = 1;
        } else {
            hi = x;
            fhi = fx;
            if (retained == -1) flo *= 0.5;
            retained = -1;
        }
        if (hi - lo <= 0.5 * mark) {
            mark = hi - lo;
            slow_steps = 0;
        } else {
            ++slow_steps;
        }
        if (fx == 0.0) break;
    }
}

}  // namespace vssw
