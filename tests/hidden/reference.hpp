#pragma once
// The reference solution, under its own namespaces (reference/<file>.cpp compiles
// solutions/<file>.cpp a second time as workbook::reference_<file>), for the hidden tests'
// domain-wide samples: the checker computes the right answer to every sampled input itself,
// from its own copy of that input. A signature that drifts from the chapter header is an
// undefined reference when the test binaries link.
#include <array>

#include "workbook/contact.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/matrix3.hpp"
#include "workbook/response_model.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::reference_inelastic {
Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2);
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact);
double energy_lost(const RigidBody& body1, const RigidBody& body2);
}  // namespace workbook::reference_inelastic

namespace workbook::reference_projection {
double depth_to_remove(double depth, const PositionCorrection& knobs);
void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs);
}  // namespace workbook::reference_projection

namespace workbook::reference_linear_impulse {
double relative_normal_velocity(const RigidBody& body1, const RigidBody& body2, const Vector3& normal);
double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal, double restitution);
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact);
}  // namespace workbook::reference_linear_impulse

namespace workbook::reference_angular_impulse {
Matrix3 world_inverse_inertia(const RigidBody& body);
Vector3 point_velocity(const RigidBody& body, const Vector3& point);
double impulse_denominator(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal);
double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal,
                         double restitution);
void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse);
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact);
}  // namespace workbook::reference_angular_impulse

namespace workbook::reference_friction {
double mix_coefficients(double mu1, double mu2);
std::array<Vector3, 2> tangent_basis(const Vector3& normal);
double tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& tangent);
std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient, double dynamic_coefficient);
double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses);
}  // namespace workbook::reference_friction
