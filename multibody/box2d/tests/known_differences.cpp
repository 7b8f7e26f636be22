// Box2D's known differences: the cross-engine tests (tests/test_engines.cpp) it cannot pass, each skipped
// with what was measured and why (tests/known_differences.hpp). Registered by multibody/box2d/engine.cmake.
#include "tests/known_differences.hpp"

namespace vssw::testing {
namespace {

[[maybe_unused]] const bool registered = register_known_differences({
    {"box2d", "VsswRestitution",
     "Box2D's sequential impulses resolve the landing with every contact found at once (new pivot, closing hinge, "
     "roller guide), restitution 0: the whole new mechanism's plastic impact (0.8252 on the Fig. 6 wall), not "
     "Eq. (19) (0.9508), which assumes no impulse at the roller. Measured on the Fig. 6 wall: 0.8261 / 0.8276 / "
     "0.8252 at 1 / 0.5 / 0.2 ms, -13.1 % against Eq. (19), +0.11 / +0.30 / +0.01 % against the whole mechanism "
     "(docs/contributing/engines.md \"Box2D\")."},
});

}  // namespace
}  // namespace vssw::testing
