// Chapter 6's families (friction): a block on an incline, which slides or sticks, and a ball
// thrown without spin, which slides and then rolls. See families.hpp for their closed forms and
// what each measures; peers.cpp runs the same scenes in the peer engines.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "families.hpp"
#include "models.hpp"
#include "workbook/time_series.hpp"

namespace workbook::accuracy {

// ---- How the workbook is given a friction coefficient ---------------------------------------
// Chapter 6 (`friction`): every body carries a dynamic coefficient `friction` and a static one
// `static_friction`, a pair's coefficient is sqrt(mu1 mu2), and the responder "friction"
// answers them. The same mu on every body, the ground included, gives the pair mu; static and
// dynamic are equal here, as in the peers on their defaults.

const ResponseModel& friction_model() { return chapter_model("friction"); }

World friction_world(std::vector<RigidBody> bodies, WorldSettings settings, const ResponseModel& model, double mu) {
    for (RigidBody& body : bodies) {
        body.friction = mu;
        body.static_friction = mu;
    }
    return World(std::move(bodies), settings, model);
}

// ---- The closed forms ------------------------------------------------------------------------

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

/// The ground y = 0, e = 0.
RigidBody ground() {
    RigidBody plane = make_immovable_plane({0.0, 1.0, 0.0}, {});
    plane.restitution = 0.0;
    return plane;
}

}  // namespace

double Incline::gravity_x() const { return g * std::sin(radians(theta_degrees)); }
double Incline::gravity_y() const { return -g * std::cos(radians(theta_degrees)); }

double Incline::acceleration(double mu) const {
    const double theta = radians(theta_degrees);
    return std::tan(theta) <= mu ? 0.0 : g * (std::sin(theta) - mu * std::cos(theta));
}

double Incline::error(double mu, double t, double x, double vx) const {
    const double a = acceleration(mu);
    const double slide = 0.5 * gravity_x() * t * t, speed = gravity_x() * t;
    return std::max(std::abs(x - 0.5 * a * t * t) / slide, std::abs(vx - a * t) / speed);
}

double ThrownBall::velocity(double t) const { return t < switch_time() ? v0 - mu * g * t : 5.0 / 7.0 * v0; }

double ThrownBall::position(double t) const {
    const double ts = std::min(t, switch_time());
    return v0 * ts - 0.5 * mu * g * ts * ts + (t > ts ? 5.0 / 7.0 * v0 * (t - ts) : 0.0);
}

double ThrownBall::spin(double t) const { return -std::min(2.5 * mu * g * t, 5.0 / 7.0 * v0) / radius; }

double ThrownBall::error(double t, double x, double vx, double spin_z) const {
    return std::max({std::abs(vx - velocity(t)) / v0, std::abs(spin_z - spin(t)) * radius / v0,
                     std::abs(x - position(t)) / (2.0 * radius)});
}

// ---- The workbook's runs -----------------------------------------------------------------------

FamilyError incline_error(const WorldSettings& settings, const ResponseModel& model) {
    const Incline incline;
    WorldSettings tilted = settings;
    tilted.gravity = {incline.gravity_x(), incline.gravity_y(), 0.0};
    FamilyError result;
    result.error = 0.0;
    for (double mu : {Incline::mu_slides, Incline::mu_sticks}) {
        RigidBody block = make_box(incline.mass, {incline.half_length, incline.half_height, incline.half_depth},
                                   {0.0, incline.half_height, 0.0});
        block.restitution = 0.0;
        World world = friction_world({block, ground()}, tilted, model, mu);
        const std::size_t steps = step_count(incline.duration, settings.time_step);
        for (std::size_t n = 0; n < steps; ++n) world.step();
        const RigidBody& b = world.bodies()[0];
        result.error = std::max(result.error, incline.error(mu, world.time(), b.position.x, b.velocity.x));
        result.steps += steps;
    }
    return result;
}

FamilyError thrown_ball_error(const WorldSettings& settings, const ResponseModel& model) {
    const ThrownBall thrown;
    RigidBody ball = make_sphere(thrown.mass, thrown.radius, {0.0, thrown.radius, 0.0}, {thrown.v0, 0.0, 0.0});
    ball.restitution = 0.0;
    WorldSettings with_gravity = settings;
    with_gravity.gravity = {0.0, -thrown.g, 0.0};
    World world = friction_world({ball, ground()}, with_gravity, model, thrown.mu);
    FamilyError result;
    result.steps = step_count(thrown.duration, settings.time_step);
    for (std::size_t n = 0; n < result.steps; ++n) world.step();
    const RigidBody& b = world.bodies()[0];
    result.error = thrown.error(world.time(), b.position.x, b.velocity.x, b.angular_velocity.z);
    return result;
}

}  // namespace workbook::accuracy
