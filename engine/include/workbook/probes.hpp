#pragma once
/// \file
/// Energy and momentum probes, measured once per step.

#include <span>

#include "workbook/rigid_body.hpp"
#include "workbook/vector3.hpp"

namespace workbook {

/// The conserved (or not) quantities of a set of bodies at one instant.
///
/// Immovable bodies have infinite mass; they stand for the environment and are left out of
/// every sum, which is why a ball bouncing off the ground does not "conserve" momentum here.
struct Probes {
    double time = 0.0;                ///< s
    double kinetic_linear = 0.0;      ///< sum of 1/2 m |v|^2, J
    double kinetic_rotational = 0.0;  ///< sum of 1/2 w . (I w), J
    double potential = 0.0;           ///< sum of -m g . x (zero at the origin), J
    Vector3 linear_momentum{};        ///< sum of m v, kg m/s
    Vector3 angular_momentum{};       ///< about the origin: sum of x cross m v + I w, kg m^2/s
    double response_energy_change = 0.0;  ///< kinetic energy change caused by this step's responses, J
    int contacts = 0;                 ///< contacts detected this step
    /// Deepest penetration among this step's contacts as detection found them, before the
    /// position correction of the same step, m; 0 when there was no contact.
    double penetration_max = 0.0;

    /// Linear plus rotational kinetic energy, J.
    [[nodiscard]] double kinetic() const { return kinetic_linear + kinetic_rotational; }
    /// Kinetic plus potential energy, J.
    [[nodiscard]] double total_energy() const { return kinetic() + potential; }
};

/// Kinetic energy (linear plus rotational) of one body; 0 for an immovable body.
double kinetic_energy(const RigidBody& body);

/// Measures every probe over `bodies` under uniform `gravity` (m/s^2). With
/// `skip_still_rotation` the rotational terms of a body that does not spin are left out
/// rather than computed as zero (the world inertia costs two matrix products); the sums are
/// the same to the bit.
Probes measure(std::span<const RigidBody> bodies, const Vector3& gravity, bool skip_still_rotation = true);

}  // namespace workbook
