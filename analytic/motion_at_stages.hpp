#pragma once
// A ground motion read at the integrator's stages (simulate.cpp).
#include <optional>

#include "ground_motion.hpp"

namespace vssw {

// A ground motion read at the integrator's stages: the twelve stages of a step under a record fall in one sample
// interval, so the interval's line is kept and the record looked up only when a time leaves it (the lookup was 10 %
// of a record run's instructions, callgrind). Values equal GroundMotion::operator() to rounding.
class MotionAtStages {
public:
    explicit MotionAtStages(const GroundMotion& m) : m_(m) {}
    double operator()(double t) const {
        if (!(t >= piece_.start && t <= piece_.end)) {
            const std::optional<GroundMotion::LinearPiece> p = m_.linear_piece(t);
            if (!p) return m_(t);  // an analytic signal, or outside the record's samples
            piece_ = *p;
        }
        return piece_.value + piece_.slope * (t - piece_.start);
    }

private:
    const GroundMotion& m_;
    mutable GroundMotion::LinearPiece piece_{1.0, 0.0, 0.0, 0.0};  // empty until the first lookup
};

}  // namespace vssw
