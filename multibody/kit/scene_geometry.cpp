#include "multibody/kit/scene_geometry.hpp"

#include <cmath>
#include <memory>
#include <optional>

#include "analytic/closed_forms.hpp"
#include "analytic/model.hpp"
#include "multibody/kit/rounded_corners.hpp"

namespace vssw::multibody {
namespace {

// Clockwise rotation by `angle` of the vector (x, y).
void turn(double angle, double x, double y, double& out_x, double& out_y) {
    out_x = x * std::cos(angle) + y * std::sin(angle);
    out_y = -x * std::sin(angle) + y * std::cos(angle);
}

}  // namespace

bool left_guide_binds(double right_corner_x, double left_corner_x, double ground_x, double b) {
    const double right_out = right_corner_x - ground_x - b, left_out = -b - (left_corner_x - ground_x);
    return left_out > right_out;
}

BlockSizes block_sizes(const WallScene& scene) {
    require_one_description(scene);
    if (scene.vssw) return {scene.vssw->b, scene.vssw->h1, scene.vssw->h2, scene.vssw->m1, scene.vssw->m2};
    return {scene.parapet->b, scene.parapet->h, 0.0, scene.parapet->m, 0.0};
}

WallPose pose_at(const WallScene& scene, double theta1) {
    if (scene.corner_radius() > 0.0) return rounded_pose_at(scene, theta1);  // rounded_corners.hpp
    const BlockSizes s = block_sizes(scene);
    const double side = theta1 < 0.0 ? -1.0 : 1.0;  // tipping towards +x turns about (+b, 0)
    WallPose p{};
    // Lower block: its centre is (-side b, h_lower) from the pivot (side b, 0), turned by theta1.
    double dx = 0.0, dy = 0.0;
    turn(theta1, -side * s.b, s.h_lower, dx, dy);
    p.lower = {side * s.b + dx, dy, theta1};
    if (!scene.vssw) return p;
    // Hinge: the lower block's top corner on the face opposite the pivot, (-side 2b, 2 h1) from the pivot.
    double hx = 0.0, hy = 0.0;
    turn(theta1, -side * 2.0 * s.b, 2.0 * s.h_lower, hx, hy);
    hx += side * s.b;
    const double theta2 = eq2_theta2_exact(*scene.vssw, theta1).value_or(0.0);
    // Upper block: its centre is (side b, h2) from the hinge corner, turned by theta2.
    double ux = 0.0, uy = 0.0;
    turn(theta2, side * s.b, s.h_upper, ux, uy);
    p.upper = {hx + ux, hy + uy, theta2};
    return p;
}

MechanismFigures mechanism_figures(const WallScene& scene) {
    const std::unique_ptr<RockingModel> model = analytic_model(scene, Kinematics::exact);
    return {model->collapse_angle(), model->unstable_equilibrium(), model->rest_threshold(0.0),
            std::abs(model->reference_energy()), model->reference_velocity()};
}

double collapse_angle(const WallScene& scene) { return analytic_model(scene, Kinematics::exact)->collapse_angle(); }
double unstable_equilibrium(const WallScene& scene) {
    return analytic_model(scene, Kinematics::exact)->unstable_equilibrium();
}
double mechanism_theta2(const WallScene& scene, double theta1) {
    if (!scene.vssw) return HUGE_VAL;
    const std::optional<double> theta2 = eq2_theta2_exact(*scene.vssw, theta1);
    return theta2 ? std::abs(*theta2) : HUGE_VAL;
}
double rest_threshold(const WallScene& scene) {
    return analytic_model(scene, Kinematics::exact)->rest_threshold(0.0);
}
double reference_energy(const WallScene& scene) {
    return std::abs(analytic_model(scene, Kinematics::exact)->reference_energy());
}
double reference_velocity(const WallScene& scene) { return analytic_model(scene, Kinematics::exact)->reference_velocity(); }

}  // namespace vssw::multibody
