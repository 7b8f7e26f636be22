#include "top_support_model.hpp"

#include <cmath>

namespace vssw {

RheonomicTerms top_support_terms(const VsswGeometry& g, double q, const TopOffsetState& top) {
    const double a = g.alpha1 - q, sa = std::sin(a), ca = std::cos(a);
    const double R1 = g.R1, R2 = g.R2;
    // Eq. (2d) and the derivatives of S = sin psi: S_q = -s cos a, S_qq = -s sin a, S_t = w'/(2 R2), S_tt = w''/(2 R2).
    const double S = g.s * sa + top.w / (2.0 * R2), c = std::sqrt(1.0 - S * S);
    const double S_q = -g.s * ca, S_qq = -g.s * sa, S_t = top.w_dot / (2.0 * R2), S_tt = top.w_ddot / (2.0 * R2);
    const double c3 = c * c * c;
    const double psi_q = S_q / c, psi_qq = S_qq / c + S_q * S_q * S / c3;
    const double psi_t = S_t / c, psi_qt = S_q * S_t * S / c3, psi_tt = S_tt / c + S_t * S_t * S / c3;
    // The upper body's centre: x2 = -R1 sin a + w / 2, y2 = 2 R1 cos a + R2 cos psi.
    const double J_x = R1 * ca, J_y = 2.0 * R1 * sa - R2 * S * psi_q;          // dr2/dq
    const double Jq_x = R1 * sa, Jq_y = -2.0 * R1 * ca - R2 * (c * psi_q * psi_q + S * psi_qq);  // d2r2/dq2
    const double Jt_y = -R2 * (c * psi_q * psi_t + S * psi_qt);                 // d2r2/dq dt (x: 0)
    const double rtt_x = 0.5 * top.w_ddot, rtt_y = -R2 * (c * psi_t * psi_t + S * psi_tt);  // d2r2/dt2
    RheonomicTerms t{};
    t.M = g.m1 * R1 * R1 + g.I1 + g.m2 * (J_x * J_x + J_y * J_y) + g.I2 * psi_q * psi_q;
    t.C = g.m2 * (J_x * Jq_x + J_y * Jq_y) + g.I2 * psi_q * psi_qq;
    t.dM_dt = 2.0 * (g.m2 * J_y * Jt_y + g.I2 * psi_q * psi_qt);
    t.F = g.m2 * (J_x * rtt_x + J_y * rtt_y) + g.I2 * psi_q * psi_tt;
    t.X = (g.m1 + g.m2) * R1 * ca;
    t.Y = g.m1 * R1 * sa + g.m2 * J_y;
    // theta2 = psi - alpha2; N at the top centre, 2 h2 cos theta2 - b sin theta2 above the hinge.
    const double s2 = S * g.cos_a2 - c * g.sin_a2, c2 = c * g.cos_a2 + S * g.sin_a2;
    t.L = 2.0 * R1 * sa - (2.0 * g.h2 * s2 + g.b * c2) * psi_q;
    return t;
}

bool holds_mechanism(const VsswGeometry& g, double q, double offset) {
    const double S = g.s * std::sin(g.alpha1 - q) + offset / (2.0 * g.R2);
    return std::abs(S) <= 1.0 && offset <= 2.0 * g.R1 * (g.sin_a1 - std::sin(g.alpha1 - q));
}

}  // namespace vssw
