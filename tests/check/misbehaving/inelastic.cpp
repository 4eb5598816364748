// A student's chapter 1 that misbehaves differently in each step, for the test of
// ./workbook check's runner (tests/check/test_check_runner.py): step 1 returns NaN, step 2
// is right, step 3 crashes, step 4 never returns and step 5 throws. The runner must report
// each on its own step and still print every step and the summary.
#include <stdexcept>

#include "inelastic.hpp"

namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    // 0/0: the NaN of a student who divides by w1 + w2 without looking.
    const double nothing = body1.inverse_mass * 0.0 + body2.inverse_mass * 0.0;
    return Vector3{nothing / nothing, 0.0, 0.0};
}

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() || body2.is_immovable()) {
        RigidBody* volatile nowhere = nullptr;
        nowhere->velocity = body1.velocity;  // step 3: a segmentation fault
    }
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) {
        volatile unsigned long spin = 0;
        for (;;) spin = spin + 1;  // step 4: never returns
    }
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    const Vector3 shared = (w2 * body1.velocity + w1 * body2.velocity) / (w1 + w2);
    body1.velocity = shared;
    body2.velocity = shared;
}

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    (void)body1;
    (void)body2;
    throw std::runtime_error("energy_lost is not written yet");
}

}  // namespace workbook::inelastic
