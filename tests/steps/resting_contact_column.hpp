#pragma once
// The world's contact solver with the student's solve_velocity (step 5) alone: the columns of
// balls that grade step 5 run through the world with the test's own prepare, warm start and
// position pass, so that a mistake of another step costs that step only. For balls touching
// through their centres the effective mass is chapter 3's reduced mass, m1 m2 / (m1 + m2); a
// column at rest needs no bounce, has no impulse of a last step to warm start with, and is
// not pushed apart within the one step the tests run.
#include "resting-contact.hpp"
#include "workbook/contact_solver.hpp"

namespace workbook::resting_contact_column {

inline void prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
                    const ContactSolverSettings& /*settings*/, const PositionCorrection& /*knobs*/, double /*dt*/) {
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        PointImpulse& p = impulses.points[i];
        p.mass = 1.0 / (body1.inverse_mass + body2.inverse_mass);
        p.bounce = 0.0;
        p.bias = 0.0;
        p.pseudo = 0.0;
    }
}

inline void no_warm_start(RigidBody& /*body1*/, RigidBody& /*body2*/, const Contact& /*contact*/,
                          const ContactImpulses& /*impulses*/) {}

inline double no_position_pass(RigidBody& /*body1*/, RigidBody& /*body2*/, const Contact& /*contact*/,
                               ContactImpulses& /*impulses*/) {
    return 0.0;
}

/// The hooks of a world whose only student code is solve_velocity().
inline constexpr ContactSolverHooks velocity_pass_alone{&prepare, &no_warm_start, &resting_contact::solve_velocity, nullptr,
                                                        &no_position_pass};

}  // namespace workbook::resting_contact_column
