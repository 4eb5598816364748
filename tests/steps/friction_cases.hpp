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
