#include "workbook/rotation.hpp"

#include <cmath>
#include <limits>

namespace workbook {

namespace {

/// Upper bound on the Newton iterations of one step. Two or three reach rounding at ordinary
/// steps, also for a thin rod tumbling end over end (where a plain fixed-point iteration,
/// contracting only by about |w| dt times the ratio of the largest to the smallest moment,
/// would diverge); the bound only matters for absurdly coarse steps, which then stay finite
/// (L is turned, never rescaled) but lose exact energy conservation.
constexpr int max_iterations = 50;

/// The cross-product matrix [v]x, with [v]x u = v x u.
Matrix3 cross_matrix(const Vector3& v) { return {{0.0, -v.z, v.y, v.z, 0.0, -v.x, -v.y, v.x, 0.0}}; }

/// The right Jacobian of the rotation group at -theta: how exp(-[theta]) v moves when theta
/// moves, d(exp(-[theta]) v) = exp(-[theta]) [v]x J dtheta. Series near zero, where the closed
/// form loses its digits to cancellation.
Matrix3 right_jacobian_of_inverse(const Vector3& theta) {
    const double a = length(theta);
    const double a2 = a * a;
    const double first = a < 1e-4 ? 0.5 - a2 / 24.0 : (1.0 - std::cos(a)) / a2;
    const double second = a < 1e-4 ? 1.0 / 6.0 - a2 / 120.0 : (a - std::sin(a)) / (a2 * a);
    const Matrix3 k = cross_matrix(theta);
    return Matrix3::identity() + k * first + k * k * second;
}


/// The rotation by the body-frame rotation vector `angle_vector` (axis times angle, rad).
Quaternion rotation_by(const Vector3& angle_vector) {
    const double angle = length(angle_vector);
    if (angle == 0.0) return {};
    return from_axis_angle(angle_vector / angle, angle);
}

}  // namespace

// The method: an implicit midpoint rule on the rotation group, solved by Newton iterations.
//
// In the body frame Euler's equations read dL/dt = L x W with W = I^-1 L (body-frame angular
// velocity). Over one step the body turns by exp(dt [W_mid]), where W_mid = I^-1 (L_n + L_n+1)/2
// is the angular velocity at the midpoint angular momentum, and the body-frame momentum turns
// the opposite way: L_n+1 = exp(-dt [W_mid]) L_n. This is the midpoint rule with the exact
// rotation in place of the Cayley approximation. Why it is the right one here:
//  - the world-frame momentum R L is unchanged by construction (the body turns one way, its
//    momentum the other), so |L| and L stay exact to rounding;
//  - the energy E = 1/2 L . I^-1 L is unchanged exactly: E_n+1 - E_n = (L_n+1 - L_n) . W_mid,
//    and turning L_n about the axis W_mid moves it perpendicular to W_mid;
//  - the scheme is symmetric (time-reversible), hence second-order accurate;
//  - a steady spin about a principal axis turns by exactly |w| dt per step.
// The explicit splittings (Dullweber, Reich and Leimkuhler; Buss) also keep L exact but let
// the energy oscillate by O(dt^2); near the tennis-racket separatrix that error moves the
// body onto another orbit, which is exactly what the figure must not show.
namespace {

/// One step of the method above, for a turn small enough that Newton's method converges.
int turn_freely(RigidBody& body, double dt) {
    const Matrix3 inverse_inertia_body = inverse(body.inertia_body);
    const Quaternion q = body.orientation;
    const Vector3 momentum_world = body.inertia_world() * body.angular_velocity;
    const Vector3 momentum_start = rotate(conjugate(q), momentum_world);  // L_n in the body frame

    // Solve G(W) = W - I^-1 (L_n + exp(-dt [W]) L_n) / 2 = 0 for the midpoint spin W by
    // Newton's method, from the explicit guess W = I^-1 L_n.
    Vector3 spin = inverse_inertia_body * momentum_start;
    // Converged when the step is down to rounding: a few ulps of W, or, for stiff bodies such
    // as thin rods whose badly conditioned Jacobian amplifies the rounding, a step near that
    // level which no longer shrinks (Newton's steps shrink quadratically until they hit it).
    const double tolerance = 4.0 * std::numeric_limits<double>::epsilon() * length(spin);
    double previous_step = std::numeric_limits<double>::infinity();
    const Matrix3 momentum_cross = cross_matrix(momentum_start);
    int iterations = 0;
    while (iterations < max_iterations) {
        ++iterations;
        const Vector3 theta = spin * dt;
        const Quaternion back = conjugate(rotation_by(theta));
        const Vector3 momentum_end = rotate(back, momentum_start);
        const Vector3 residual = spin - inverse_inertia_body * ((momentum_start + momentum_end) * 0.5);
        const Matrix3 jacobian = Matrix3::identity() + inverse_inertia_body * to_matrix(back) * momentum_cross *
                                                           right_jacobian_of_inverse(theta) * (-0.5 * dt);
        // A singular Jacobian (only at absurd steps) gives the zero matrix and stops the solve.
        const Vector3 step = inverse(jacobian) * residual;
        spin -= step;
        const double step_length = length(step);
        if (!(step_length > tolerance) || (step_length < 1e3 * tolerance && step_length > 0.5 * previous_step)) break;
        previous_step = step_length;
    }
    const Quaternion turn = rotation_by(spin * dt);
    body.orientation = normalized(q * turn);
    body.update_world_inertia();
    // w from the conserved world-frame momentum, with one step of iterative refinement:
    // without it, (R I R^T)(R I^-1 R^T) differs from the identity by a few ulps in a way that
    // repeats from one step to the next, and L would drift steadily by that much per step.
    // With it, L as the probes measure it, (R I R^T) w, matches the start of the step to
    // rounding, and what rounding is left does not add up.
    const Matrix3 inertia_world = body.inertia_world();
    body.angular_velocity = body.inverse_inertia_world * momentum_world;
    body.angular_velocity += body.inverse_inertia_world * (momentum_world - inertia_world * body.angular_velocity);
    return iterations;
}

}  // namespace

bool is_isotropic(const Matrix3& inertia) {
    const double i = inertia(0, 0);
    return inertia == Matrix3::diagonal({i, i, i});
}

double largest_spin(const RigidBody& body) {
    // |w|^2 I_min <= w . I w = 2 E, and 1 / I_min <= |I^-1|_F (the Frobenius norm bounds the
    // largest eigenvalue of I^-1), so |w| <= sqrt(2 E |I^-1|_F) wherever the spin wanders.
    double norm_squared = 0.0;
    for (const double e : inverse(body.inertia_body).m) norm_squared += e * e;
    const double twice_energy = dot(body.angular_velocity, body.inertia_world() * body.angular_velocity);
    return std::sqrt(twice_energy * std::sqrt(norm_squared));
}

int advance_free_rotation(RigidBody& body, double dt) {
    if (body.angular_velocity == Vector3{} || dt == 0.0) return 0;
    if (is_isotropic(body.inertia_body)) {
        body.orientation = integrate(body.orientation, body.angular_velocity, dt);
        body.update_world_inertia();
        return 0;
    }
    // Newton's method converges from the explicit guess while the body turns by less than
    // about 3 rad in a step (measured: a box on a skew axis gained 29 % of its energy at
    // 4 rad a step before sub-steps). A faster spin is followed in equal sub-steps of at most
    // max_turn_per_substep each, judged by the spin now; each sub-step keeps the energy, so
    // the step does too.
    const double turn = length(body.angular_velocity) * std::abs(dt);
    int substeps = 1;
    if (turn > max_turn_per_substep)
        substeps = static_cast<int>(std::min(std::ceil(turn / max_turn_per_substep), double{max_substeps}));
    if (substeps == 1) return turn_freely(body, dt);
    int iterations = 0;
    const double h = dt / substeps;
    for (int k = 0; k < substeps; ++k) iterations += turn_freely(body, h);
    return iterations;
}

void advance_kinematic(RigidBody& body, double dt) {
    if (body.velocity != Vector3{}) body.position += body.velocity * dt;
    if (body.angular_velocity != Vector3{}) body.orientation = integrate(body.orientation, body.angular_velocity, dt);
}

}  // namespace workbook
