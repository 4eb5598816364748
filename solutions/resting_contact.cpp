// Reference solution for chapter 5, resting contact.
#include "resting-contact.hpp"

#include <algorithm>
#include <cmath>

#include "workbook/restitution.hpp"

namespace workbook::resting_contact {

// The solver calls these in its inner loop, many times a step: they read the world inverse
// inertia the world keeps current (RigidBody::inverse_inertia_world) instead of computing it
// again from the orientation as chapter 4's steps do; the numbers are the same.
namespace {

Vector3 point_velocity(const RigidBody& body, const Vector3& point) {
    return body.velocity + cross(body.angular_velocity, point - body.position);
}

double normal_velocity(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    return dot(point_velocity(body1, point) - point_velocity(body2, point), normal);
}

void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    body1.velocity += body1.inverse_mass * impulse;
    body1.angular_velocity += body1.inverse_inertia_world * cross(point - body1.position, impulse);
    body2.velocity -= body2.inverse_mass * impulse;
    body2.angular_velocity -= body2.inverse_inertia_world * cross(point - body2.position, impulse);
}

}  // namespace

double normal_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    // k = 1/m1 + 1/m2 + n . ((I1^-1 (r1 x n)) x r1 + (I2^-1 (r2 x n)) x r2), chapter 4's denominator.
    const Vector3 r1 = point - body1.position;
    const Vector3 r2 = point - body2.position;
    const Vector3 turn1 = cross(body1.inverse_inertia_world * cross(r1, normal), r1);
    const Vector3 turn2 = cross(body2.inverse_inertia_world * cross(r2, normal), r2);
    const double k = body1.inverse_mass + body2.inverse_mass + dot(normal, turn1 + turn2);
    return k > 0.0 ? 1.0 / k : 0.0;
}

double accumulate(double& accumulated, double increment) {
    // Clamp the running sum, not the increment: a later pass may take back what an earlier
    // one gave too much, as long as the contact never ends up pulling.
    const double before = accumulated;
    accumulated = std::max(before + increment, 0.0);
    return accumulated - before;
}

namespace {

/// One pass over the points towards `target`, summing into `sum`; the largest change of a
/// point's normal velocity. The same numbers as point_velocity() and apply_impulse() above,
/// with each lever arm computed once per point and an immovable body (inverse mass 0, which
/// no impulse changes) left alone: this loop is most of the time of a pile's step.
double pass(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
            double PointImpulse::*target, double PointImpulse::*sum) {
    const bool moves1 = !body1.is_immovable(), moves2 = !body2.is_immovable();
    double largest = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        PointImpulse& p = impulses.points[i];
        if (p.mass == 0.0) continue;
        const Vector3& at = contact.points[i].position;
        const Vector3 r1 = at - body1.position;
        const Vector3 r2 = at - body2.position;
        const Vector3 v1 = body1.velocity + cross(body1.angular_velocity, r1);
        const Vector3 v2 = body2.velocity + cross(body2.angular_velocity, r2);
        const double u = dot(v1 - v2, contact.normal);
        const double applied = accumulate(p.*sum, p.mass * (p.*target - u));
        if (applied == 0.0) continue;
        const Vector3 impulse = applied * contact.normal;
        if (moves1) {
            body1.velocity += body1.inverse_mass * impulse;
            body1.angular_velocity += body1.inverse_inertia_world * cross(r1, impulse);
        }
        if (moves2) {
            body2.velocity -= body2.inverse_mass * impulse;
            body2.angular_velocity -= body2.inverse_inertia_world * cross(r2, impulse);
        }
        largest = std::max(largest, std::abs(applied) / p.mass);
    }
    return largest;
}

}  // namespace

void prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
             const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt) {
    const double e = combined_restitution(body1, body2);
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        PointImpulse& p = impulses.points[i];
        const ContactPoint& point = contact.points[i];
        p.mass = normal_mass(body1, body2, point.position, contact.normal);
        const double u = normal_velocity(body1, body2, point.position, contact.normal);
        p.bounce = u < -settings.bounce_threshold ? -e * u : 0.0;
        p.bias = std::min(knobs.fraction * std::max(point.penetration - knobs.slop, 0.0), settings.max_push) / dt;
        p.pseudo = 0.0;
    }
}

void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const double j = impulses.points[i].normal;
        if (j != 0.0) apply_impulse(body1, body2, contact.points[i].position, j * contact.normal);
    }
}

double solve_velocity(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    return pass(body1, body2, contact, impulses, &PointImpulse::bounce, &PointImpulse::normal);
}

double solve_position(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    return pass(body1, body2, contact, impulses, &PointImpulse::bias, &PointImpulse::pseudo);
}

}  // namespace workbook::resting_contact
