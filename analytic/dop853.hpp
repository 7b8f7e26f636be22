#pragma once
// Dormand & Prince's explicit Runge-Kutta 8(5,3) (Hairer, Norsett & Wanner, Solving ODEs I, Sect. II.10): 8th order,
// error estimated from embedded 5th- and 3rd-order solutions, and a 7th-order continuous extension that costs three
// more evaluations and is built only for the steps that need it (an event, a turning point, an output time).
// Adaptive by default; a fixed step (for convergence tests) when min_step == max_step.
//
// One step is taken at a time: the caller decides where to stop (breakpoints, events) and can redo a step with any
// size from the same start to land exactly on an event.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "dop853_tableau.hpp"

namespace vssw {

template <std::size_t N>
using Vec = std::array<double, N>;

struct StepControl {
    double rtol = 1e-10;
    double max_step = 0.25;   // [s] an upper bound only; records' breakpoints and the tolerance set the step
    double min_step = 1e-14;  // [s]
    double safety = 0.9;
};

// A trial step: its stages, its end, and (once built) its continuous extension.
template <std::size_t N>
struct RkStep {
    double t0 = 0.0, h = 0.0;
    Vec<N> y0{}, y1{};
    std::array<Vec<N>, dop853::kExtendedStages> k{};  // k[12] is the derivative at the end (first stage of the next)
    std::array<Vec<N>, 7> F{};
    bool dense_ready = false;

    const Vec<N>& end_derivative() const { return k[dop853::kStages]; }
    // State at t in [t0, t0 + h]; requires the continuous extension (Dop853::make_dense).
    Vec<N> at(double t) const {
        Vec<N> y{};
        for (std::size_t i = 0; i < N; ++i) y[i] = component_at(t, i);
        return y;
    }
    // Component i of at(t), alone (the event searches follow one component through a dozen evaluations).
    double component_at(double t, std::size_t i) const {
        const double x = (t - t0) / h, x1 = 1.0 - x;
        double v = F[6][i];
        v = F[5][i] + x * v;
        v = F[4][i] + x1 * v;
        v = F[3][i] + x * v;
        v = F[2][i] + x1 * v;
        v = F[1][i] + x * v;
        v = F[0][i] + x1 * v;
        return y0[i] + x * v;
    }
};

template <std::size_t N, class Rhs>
class Dop853 {
public:
    // scale[i] sets the absolute size of component i: errors are measured against rtol * max(scale, |y|).
    Dop853(Rhs rhs, StepControl control, Vec<N> scale)
        : f_(rhs),
          c_(control),
          scale_(scale),
          // Just below (safety / kMaxGrowth)^8, where safety / err^(1/8) is kMaxGrowth: every error norm under it
          // gets the largest growth, whatever the rounding of the roots.
          err_at_max_growth_(std::pow(control.safety / kMaxGrowth, 8) * (1.0 - 1e-9)) {}

    // Trial step of size h from (t, y) whose derivative there is dy; returns the weighted error norm (<= 1: accept).
    double step(double t, const Vec<N>& y, const Vec<N>& dy, double h, RkStep<N>& s) const {
        using namespace dop853;
        s.t0 = t;
        s.h = h;
        s.y0 = y;
        s.dense_ready = false;
        s.k[0] = dy;
        stages<1>(s, std::make_index_sequence<kStages>{});  // stage kStages (the new state) has the weights b
        // Hairer's error norm: the 5th-order estimate, damped by the 3rd-order one where it is small.
        double err5 = 0.0, err3 = 0.0;
        for (std::size_t n = 0; n < N; ++n) {
            const double e5n = weighted_sum<kEstimate5>(s.k, n, std::make_index_sequence<kStages>{});
            const double e3n = weighted_sum<kStages>(s.k, n, std::make_index_sequence<kStages>{}) -
                               (bhh[0] * s.k[0][n] + bhh[1] * s.k[8][n] + bhh[2] * s.k[11][n]);
            const double sc = c_.rtol * std::max({scale_[n], std::abs(y[n]), std::abs(s.y1[n])});
            err5 += (e5n / sc) * (e5n / sc);
            err3 += (e3n / sc) * (e3n / sc);
        }
        if (err5 == 0.0 && err3 == 0.0) return 0.0;
        return std::abs(h) * err5 / std::sqrt((err5 + 0.01 * err3) * static_cast<double>(N));
    }

    // Builds the continuous extension of an accepted step (three more evaluations).
    void make_dense(RkStep<N>& s) const {
        using namespace dop853;
        if (s.dense_ready) return;
        stages<kStages + 1>(s, std::make_index_sequence<kExtendedStages - kStages - 1>{});
        const double h = s.h;
        for (std::size_t n = 0; n < N; ++n) {
            const double dy = s.y1[n] - s.y0[n];
            s.F[0][n] = dy;
            s.F[1][n] = h * s.k[0][n] - dy;
            s.F[2][n] = 2.0 * dy - h * (s.k[kStages][n] + s.k[0][n]);
            s.F[3][n] = h * weighted_sum<kDense0>(s.k, n, std::make_index_sequence<kExtendedStages>{});
            s.F[4][n] = h * weighted_sum<kDense0 + 1>(s.k, n, std::make_index_sequence<kExtendedStages>{});
            s.F[5][n] = h * weighted_sum<kDense0 + 2>(s.k, n, std::make_index_sequence<kExtendedStages>{});
            s.F[6][n] = h * weighted_sum<kDense0 + 3>(s.k, n, std::make_index_sequence<kExtendedStages>{});
        }
        s.dense_ready = true;
    }

    // Next step size from an error norm (Hairer's controller: growth limited to [1/3, 6]).
    double next_step(double h, double err) const {
        if (fixed_step()) return c_.max_step;
        // A step far more accurate than asked (every step a record's samples cut short) grows the most: decided by
        // a comparison, which the processor predicts, so that the next step need not wait for the roots below
        // (three dependent square roots and a division: a tenth of a record run's time per step, perf).
        if (err <= err_at_max_growth_) return std::clamp(h * kMaxGrowth, c_.min_step, c_.max_step);
        // err^(-1/8) as three square roots: the same number to rounding, four instructions for std::pow's ~70
        // (callgrind).
        const double factor = std::clamp(c_.safety / std::sqrt(std::sqrt(std::sqrt(err))), 1.0 / 3.0, kMaxGrowth);
        return std::clamp(h * factor, c_.min_step, c_.max_step);
    }
    bool fixed_step() const { return c_.min_step >= c_.max_step; }
    Vec<N> rhs(double t, const Vec<N>& y) const { return f_(t, y); }

private:
    // Rows of weights addressed by one index, so that every sum below unrolls at compile time and skips the
    // tableau's zeros: rows 0..15 of a, then e5, then the four rows of d.
    static constexpr int kEstimate5 = dop853::kExtendedStages;
    static constexpr int kDense0 = kEstimate5 + 1;
    static constexpr double weight(int row, std::size_t j) {
        if (row < dop853::kExtendedStages) return dop853::a[row][j];
        if (row == kEstimate5) return j < dop853::kStages + 1 ? dop853::e5[j] : 0.0;
        return dop853::d[row - kDense0][j];
    }
    template <int Row, std::size_t J>
    static void add_term(double& sum, const std::array<Vec<N>, dop853::kExtendedStages>& k, std::size_t n) {
        if constexpr (weight(Row, J) != 0.0) sum += weight(Row, J) * k[J][n];
    }
    template <int Row, std::size_t... J>
    static double weighted_sum(const std::array<Vec<N>, dop853::kExtendedStages>& k, [[maybe_unused]] std::size_t n,
                               std::index_sequence<J...>) {
        double sum = 0.0;
        (add_term<Row, J>(sum, k, n), ...);
        return sum;
    }
    // Stage I: y + h sum_j a[I][j] k_j, evaluated at t + c_I h; stage kStages is the new state itself.
    // The newest stage's term is added last through one product with h a[I][I-1]: the stage waits on that stage's
    // right-hand side alone, and the rest of the sum is ready before it.
    template <int I>
    void stage(RkStep<N>& s) const {
        Vec<N> yi = s.y0;
        constexpr std::size_t last = static_cast<std::size_t>(I) - 1;
        static_assert(weight(I, last) != 0.0, "every stage of the tableau uses the one before it");
        const double h_last = s.h * weight(I, last);
        for (std::size_t n = 0; n < N; ++n) {
            const double rest = last == 0 ? 0.0 : weighted_sum<I>(s.k, n, std::make_index_sequence<last>{});
            yi[n] += s.h * rest + h_last * s.k[last][n];
        }
        if constexpr (I == dop853::kStages) s.y1 = yi;
        s.k[I] = f_(s.t0 + dop853::c[I] * s.h, yi);
    }
    template <int First, std::size_t... I>
    void stages(RkStep<N>& s, std::index_sequence<I...>) const {
        (stage<First + static_cast<int>(I)>(s), ...);
    }

    static constexpr double kMaxGrowth = 6.0;
    Rhs f_;
    StepControl c_;
    Vec<N> scale_;
    double err_at_max_growth_;
};

}  // namespace vssw
