#pragma once
// Test doubles for chapter 5's functions, for the contact solver's tests without chapter code:
// linear impulses along the normal at the centres, which are exact for balls in a column, so
// that the solver's answer is known in closed form.
#include <algorithm>
#include <cmath>

#include "workbook/contact_solver.hpp"
#include "workbook/response_model.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::testing {

inline double normal_velocity(const RigidBody& body1, const RigidBody& body2, const Contact& contact) {
    return dot(body1.velocity - body2.velocity, contact.normal);
}

inline void prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
                    const ContactSolverSettings&, const PositionCorrection& knobs, double dt) {
    PointImpulse& p = impulses.points[0];
    const double k = body1.inverse_mass + body2.inverse_mass;
    p.mass = k > 0.0 ? 1.0 / k : 0.0;
    p.bounce = 0.0;
    p.bias = knobs.fraction * std::max(contact.penetration - knobs.slop, 0.0) / dt;
    p.pseudo = 0.0;
}

inline void push(RigidBody& body1, RigidBody& body2, const Contact& contact, double j) {
    body1.velocity += contact.normal * (j * body1.inverse_mass);
    body2.velocity -= contact.normal * (j * body2.inverse_mass);
}

inline void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    push(body1, body2, contact, impulses.points[0].normal);
}

inline double pass(RigidBody& body1, RigidBody& body2, const Contact& contact, double target, double& sum, double mass) {
    const double before = sum;
    sum = std::max(before + mass * (target - normal_velocity(body1, body2, contact)), 0.0);
    push(body1, body2, contact, sum - before);
    return mass > 0.0 ? std::abs(sum - before) / mass : 0.0;
}

inline double solve_velocity(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    PointImpulse& p = impulses.points[0];
    return pass(body1, body2, contact, p.bounce, p.normal, p.mass);
}

inline double solve_position(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    PointImpulse& p = impulses.points[0];
    return pass(body1, body2, contact, p.bias, p.pseudo, p.mass);
}

inline constexpr ContactSolverHooks solver_hooks{&prepare, &warm_start, &solve_velocity, nullptr, &solve_position};
inline constexpr ResponseModel solver_model{"test-solver", nullptr, nullptr, &solver_hooks};

}  // namespace workbook::testing
