#include "bench/floor/floor_step.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "multibody/kit/scene_geometry.hpp"

namespace vssw::yardstick {
namespace {

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// A corner of a body in the world: its centre plus the local offset (sx half_w, sy half_h) turned by the angle.
void corner(const FloorWall::Body& body, double sx, double sy, double& x, double& y) {
    const double c = std::cos(body.phi), s = std::sin(body.phi);
    const double lx = sx * body.half_w, ly = sy * body.half_h;
    x = body.x + c * lx - s * ly;
    y = body.y + s * lx + c * ly;
}

// A contact of body b's point (px, py) at `gap` along n against body a (or the fixed world, a = -1): the row's
// effective masses and the normal velocity it allows, from the positions at the step's start.
void set_row(FloorWall::Contact& c, const FloorWall::Body* a, const FloorWall::Body& b, double px, double py,
             double nx, double ny, double gap, double dt, double baumgarte) {
    c.nx = nx;
    c.ny = ny;
    c.gap = gap;
    c.ra_x = a ? px - a->x : 0.0;
    c.ra_y = a ? py - a->y : 0.0;
    c.rb_x = px - b.x;
    c.rb_y = py - b.y;
    const double tx = ny, ty = -nx;
    const auto inverse_mass = [&](double dx, double dy) {
        double k = b.inv_m + b.inv_i * std::pow(cross(c.rb_x, c.rb_y, dx, dy), 2);
        if (a) k += a->inv_m + a->inv_i * std::pow(cross(c.ra_x, c.ra_y, dx, dy), 2);
        return k;
    };
    c.k_n = 1.0 / inverse_mass(nx, ny);
    c.k_t = 1.0 / inverse_mass(tx, ty);
    // Open by `gap`: it may close by that much in this step (speculative). Overlapping: pushed out by a share of it.
    c.target_vn = gap > 0.0 ? -gap / dt : -baumgarte * gap / dt;
}

}  // namespace

FloorWall::FloorWall(const multibody::WallScene& scene, double theta0, const FloorSettings& settings)
    : settings_(settings) {
    if (!scene.vssw || scene.corner_radius() > 0.0)
        throw std::invalid_argument("the floor is the square-cornered two-block wall: give it a VSSW scene");
    if (!(settings.dt > 0.0) || settings.iterations < 0 || !(settings.mu >= 0.0) || !(settings.margin >= 0.0) ||
        !(settings.baumgarte >= 0.0 && settings.baumgarte <= 1.0))
        throw std::invalid_argument("floor settings out of range (dt > 0, iterations >= 0, mu >= 0, margin >= 0, "
                                    "baumgarte in [0, 1])");
    const multibody::BlockSizes s = multibody::block_sizes(scene);
    const multibody::WallPose pose = multibody::pose_at(scene, theta0);
    b_ = s.b;
    g_ = scene.gravity();
    const auto body = [](const multibody::BlockPose& p, double m, double hw, double hh) {
        // A solid rectangle's moment about its centre: m ((2 hw)^2 + (2 hh)^2) / 12.
        return Body{p.x, p.y, -p.angle, 0.0, 0.0, 0.0, 1.0 / m, 3.0 / (m * (hw * hw + hh * hh)), hw, hh};
    };
    body_[0] = body(pose.lower, s.m_lower, s.b, s.h_lower);
    body_[1] = body(pose.upper, s.m_upper, s.b, s.h_upper);
}

double FloorWall::theta1() const { return -body_[0].phi; }
double FloorWall::theta1_dot() const { return -body_[0].w; }
double FloorWall::lower_y() const { return body_[0].y; }
int FloorWall::contacts() const { return active_; }

void FloorWall::find_contacts() {
    const double dt = settings_.dt, beta = settings_.baumgarte;
    const Body& lower = body_[0];
    const Body& upper = body_[1];
    // The lower block's top face: its outward normal and a point on it.
    const double fnx = -std::sin(lower.phi), fny = std::cos(lower.phi);
    const double fx = lower.x + lower.half_h * fnx, fy = lower.y + lower.half_h * fny;
    for (int k = 0; k < 6; ++k) {
        Contact& c = contact_[k];
        const double side = (k % 2 == 0) ? -1.0 : 1.0;
        const bool was_active = c.active;
        double px = 0.0, py = 0.0;
        if (k < 2) {  // base corners on the ground (y = 0)
            corner(lower, side, -1.0, px, py);
            c.a = -1, c.b = 0, c.mu = settings_.mu;
            set_row(c, nullptr, lower, px, py, 0.0, 1.0, py, dt, beta);
        } else if (k < 4) {  // the upper block's bottom corners on the lower block's top face
            corner(upper, side, -1.0, px, py);
            c.a = 0, c.b = 1, c.mu = settings_.mu;
            set_row(c, &lower, upper, px, py, fnx, fny, (px - fx) * fnx + (py - fy) * fny, dt, beta);
        } else {  // the upper block's top corners against the roller's guides, x = -b and x = +b, frictionless
            corner(upper, side, 1.0, px, py);
            c.a = -1, c.b = 1, c.mu = 0.0;
            set_row(c, nullptr, upper, px, py, -side, 0.0, b_ - side * px, dt, beta);
        }
        c.active = c.gap < settings_.margin;
        if (!c.active || !was_active) c.p_n = c.p_t = 0.0;  // a new contact starts cold
    }
}

void FloorWall::apply(const Contact& c, double p_n, double p_t) {
    const double px = p_n * c.nx + p_t * c.ny, py = p_n * c.ny - p_t * c.nx;  // tangent (ny, -nx)
    Body& b = body_[c.b];
    b.vx += px * b.inv_m;
    b.vy += py * b.inv_m;
    b.w += cross(c.rb_x, c.rb_y, px, py) * b.inv_i;
    if (c.a < 0) return;
    Body& a = body_[c.a];
    a.vx -= px * a.inv_m;
    a.vy -= py * a.inv_m;
    a.w -= cross(c.ra_x, c.ra_y, px, py) * a.inv_i;
}

void FloorWall::warm_start() {
    for (const Contact& c : contact_)
        if (c.active) apply(c, c.p_n, c.p_t);
}

void FloorWall::solve_sweep() {
    for (Contact& c : contact_) {
        if (!c.active) continue;
        const Body& b = body_[c.b];
        const Body* a = c.a < 0 ? nullptr : &body_[c.a];
        // Velocity of the contact point on b relative to a.
        double vx = 0.0, vy = 0.0;
        const auto relative_velocity = [&] {
            vx = b.vx - b.w * c.rb_y, vy = b.vy + b.w * c.rb_x;
            if (a) vx -= a->vx - a->w * c.ra_y, vy -= a->vy + a->w * c.ra_x;
        };
        relative_velocity();
        if (c.mu > 0.0) {  // friction first, clamped by the normal impulse so far
            const double vt = vx * c.ny - vy * c.nx;
            const double limit = c.mu * c.p_n;
            const double p_t = std::clamp(c.p_t - c.k_t * vt, -limit, limit);
            apply(c, 0.0, p_t - c.p_t);
            c.p_t = p_t;
            relative_velocity();
        }
        const double vn = vx * c.nx + vy * c.ny;
        const double p_n = std::max(c.p_n + c.k_n * (c.target_vn - vn), 0.0);
        apply(c, p_n - c.p_n, 0.0);
        c.p_n = p_n;
    }
}

void FloorWall::step(double a_h) {
    const double dt = settings_.dt;
    for (Body& body : body_) {  // gravity tilted by the ground's acceleration (the ground's frame)
        body.vx -= a_h * dt;
        body.vy -= g_ * dt;
    }
    find_contacts();
    active_ = 0;
    for (const Contact& c : contact_) active_ += c.active ? 1 : 0;
    warm_start();
    for (int i = 0; i < settings_.iterations; ++i) solve_sweep();
    for (Body& body : body_) {
        body.x += dt * body.vx;
        body.y += dt * body.vy;
        body.phi += dt * body.w;
    }
}

multibody::Trajectory run_floor(const multibody::WallScene& scene, double theta0, double t_end,
                                const FloorSettings& settings, const std::function<double(double)>& a_h) {
    FloorWall wall(scene, theta0, settings);
    const long steps = std::lround(t_end / settings.dt);
    multibody::Trajectory traj;
    traj.samples.reserve(static_cast<std::size_t>(steps) + 1);
    traj.samples.push_back(multibody::motion_sample(0.0, wall.theta1(), wall.theta1_dot()));
    for (long k = 0; k < steps; ++k) {
        const double t = static_cast<double>(k) * settings.dt;
        wall.step(a_h ? a_h(t + 0.5 * settings.dt) : 0.0);
        traj.samples.push_back(multibody::motion_sample(t + settings.dt, wall.theta1(), wall.theta1_dot()));
    }
    traj.steps = steps;
    return traj;
}

}  // namespace vssw::yardstick
