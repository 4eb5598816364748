#pragma once
// Cases shared by chapter 6's public and hidden step tests. Nothing here computes friction:
// it builds the situations and calls the student's functions.
#include <array>
#include <cmath>

#include "friction.hpp"
#include "workbook/contact.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::friction_cases {

/// A pair's coefficient as the student's own step 1 mixes `mu1` and `mu2`, so that the cases
/// of step 5 grade the pass and not step 1 again; the geometric mean itself while step 1 gives
/// no positive finite value for positive coefficients (unfinished).
inline double pair_coefficient(double mu1, double mu2) {
    const double mixed = friction::mix_coefficients(mu1, mu2);
    if (mu1 > 0.0 && mu2 > 0.0 && !(std::isfinite(mixed) && mixed > 0.0)) return std::sqrt(mu1 * mu2);
    return mixed;
}

/// The friction impulse that stops a slip needing `stop` (kg m/s), or, beyond mu_s J_n, the
/// sliding one mu_d J_n.
inline double coulomb(double stop, double normal_impulse, double mu_s, double mu_d) {
    return stop <= mu_s * normal_impulse ? stop : mu_d * normal_impulse;
}

/// A solid ball of mass `mass` and radius `radius` resting on the ground z = 0, with dynamic
/// and static coefficients `mu_d` and `mu_s` (the ground has the same, so the pair has them too).
struct BallOnSlope {
    RigidBody ball;
    RigidBody ground;
    Contact contact;
};

inline BallOnSlope ball_on_slope(double mass, double radius, double mu_d, double mu_s) {
    BallOnSlope s{make_sphere(mass, radius, {0, 0, radius}), make_immovable_plane({0, 0, 1}, {0, 0, 0}), Contact{}};
    s.ball.friction = s.ground.friction = mu_d;
    s.ball.static_friction = s.ground.static_friction = mu_s;
    s.contact.normal = {0, 0, 1};
    s.contact.add_point({0, 0, 0}, 0.0);
    return s;
}

/// `steps` steps of `dt` of a ball on a slope of angle `theta` (rad), seen in the slope's own
/// frame: the ground is z = 0 and gravity g (sin theta, 0, -cos theta) pulls down the slope
/// along +x. Each step, as the world's contact solver does for one point: gravity, then the
/// normal impulse that stops the ball sinking (m g cos theta dt, exact here), then one call of
/// the student's solve_friction() with that accumulated normal impulse and no friction yet
/// (a single point whose tangents share one mass needs one pass). The ball's centre stays
/// over the contact point: only velocities matter.
inline void roll_down(BallOnSlope& s, double theta, double dt, int steps, double g = 9.81) {
    const Vector3 gravity{g * std::sin(theta), 0.0, -g * std::cos(theta)};
    const double mass = s.ball.mass();
    for (int i = 0; i < steps; ++i) {
        s.ball.velocity += gravity * dt;
        ContactImpulses impulses;
        impulses.points[0].mass = mass;
        impulses.points[0].normal = -mass * s.ball.velocity.z;
        s.ball.velocity.z = 0.0;
        (void)friction::solve_friction(s.ball, s.ground, s.contact, impulses);
    }
}

}  // namespace workbook::friction_cases

namespace workbook::friction_cases {

/// The speed down the slope and the spin of a ball after roll_down() for `t` seconds, from the
/// laws: rolling at 5/7 g sin theta while mu_s >= 2/7 tan theta, else sliding at
/// g (sin theta - mu_d cos theta) and spinning up at 5/2 mu_d g cos theta / r.
struct SlopeMotion {
    double speed = 0.0;
    double spin = 0.0;
    bool rolls = false;
};

inline SlopeMotion slope_motion(double theta, double g, double t, double radius, double mu_s, double mu_d) {
    if (mu_s >= 2.0 / 7.0 * std::tan(theta)) {
        const double v = 5.0 / 7.0 * g * std::sin(theta) * t;
        return {v, v / radius, true};
    }
    return {g * (std::sin(theta) - mu_d * std::cos(theta)) * t, 2.5 * mu_d * g * std::cos(theta) / radius * t, false};
}

}  // namespace workbook::friction_cases
