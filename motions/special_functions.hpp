#pragma once
// The few special functions the stochastic model needs, written here so that every platform computes the same
// numbers: the regularized incomplete gamma and beta functions, their inverses, and the standard normal distribution.
// Each inverse is a bisection to the last bits: slow next to Newton's method, but it never leaves its bracket, and the
// generator calls it a few dozen times a motion.

namespace vssw::motions {

// P(a, x) = gamma(a, x) / Gamma(a), the regularized lower incomplete gamma function; a > 0, x >= 0.
double gamma_p(double a, double x);
// The x >= 0 with gamma_p(a, x) = p, for 0 < p < 1.
double gamma_p_inverse(double a, double p);
// I_x(a, b), the regularized incomplete beta function; a, b > 0, 0 <= x <= 1.
double beta_i(double a, double b, double x);
// The x in [0, 1] with beta_i(a, b, x) = p, for 0 <= p <= 1.
double beta_i_inverse(double a, double b, double p);
// Phi(x), the standard normal distribution function, and its inverse (0 < p < 1).
double normal_cdf(double x);
double normal_quantile(double p);

}  // namespace vssw::motions
