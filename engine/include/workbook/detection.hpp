#pragma once
/// \file
/// Narrow-phase collision detection: sphere-sphere and sphere-plane; pairs with a box are in
/// box_detection.hpp, and collide() dispatches to both.

#include <optional>

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

/// The normal used when two sphere centres coincide and no direction can be derived from
/// the geometry. Any unit vector is a valid separating direction there; a fixed one keeps
/// the result reproducible and free of NaN.
inline constexpr Vector3 coincident_centres_normal{0.0, 1.0, 0.0};

/// The contact between two spheres, or nothing when they do not overlap. Touching without
/// overlap (distance == r1 + r2) is not a contact.
std::optional<Contact> collide_spheres(const RigidBody& sphere1, const RigidBody& sphere2);

/// The contact between a sphere (body 1) and a plane (body 2); the normal is the plane's normal.
std::optional<Contact> collide_sphere_plane(const RigidBody& sphere, const RigidBody& plane);

/// Dispatches on the two shapes. The indices are copied into the result; when the pair is
/// given plane-first the bodies are swapped so that the normal convention still holds.
std::optional<Contact> collide(const RigidBody& a, std::uint32_t index_a, const RigidBody& b, std::uint32_t index_b);

/// The narrow phase in two halves, for the world's loop: overlaps() decides, cheaply (no
/// square root, nothing built), exactly when collide() would return a contact; then
/// write_contact() fills a default-constructed Contact in place, without the copy an
/// optional return costs (a Contact has room for four points, 184 bytes).
bool overlaps(const RigidBody& a, const RigidBody& b);

/// The sphere-sphere test and writer on plain numbers (body 1 at centre1), for loops that keep
/// the numbers apart from the bodies; overlaps() and write_contact() give the same bits.
bool spheres_overlap(const Vector3& centre1, double radius1, const Vector3& centre2, double radius2);
/// See spheres_overlap(); `contact` must be a default Contact, its indices are left to the caller.
void write_spheres(const Vector3& centre1, double radius1, const Vector3& centre2, double radius2, Contact& contact);
/// The sphere-plane test on plain numbers: a plane through `point` with unit world `normal`.
bool sphere_plane_overlap(const Vector3& centre, double radius, const Vector3& point, const Vector3& normal);
/// See sphere_plane_overlap(); the sphere is body 1.
void write_sphere_plane(const Vector3& centre, double radius, const Vector3& point, const Vector3& normal, Contact& contact);

/// How far apart two spheres may be and still get a speculative contact, m: the solver's
/// speculative `distance` (ContactSolverSettings::speculative_distance; 0 for none, and then
/// 0) plus how far each sphere travelled in the step (`travel1`, `travel2`; 0 without the
/// swept test). The solve may stop a sphere that is still moving at its own speed, and so
/// close its gap to a neighbour that keeps going by up to that speed times the step: two
/// balls falling one above the other 2 cm apart at 3 m/s, the lower one stopped by what it
/// lands on, end the step 3 cm into each other unless their pair is solved with the rest.
inline double speculative_reach(double distance, double travel1, double travel2) {
    return distance > 0.0 ? distance + travel1 + travel2 : 0.0;
}

/// The reach of the speculative contacts of the pair a, b: speculative_reach(distance,
/// travel_a, travel_b), or only `distance` when one of the two is a plane, which does not move.
double speculative_reach(const RigidBody& a, const RigidBody& b, double distance, double travel_a, double travel_b);

/// Speculative contacts (ContactSolverSettings::speculative_distance): whether two spheres, or
/// a sphere and a plane, are apart by less than the pair's speculative_reach(a, b, ...) (or
/// overlap); write_contact() then writes their contact, with a negative depth (the gap) when
/// they are apart. For a pair with a box, whether the bounding spheres come that near:
/// write_contact(), given the pair's reach, decides and writes the speculative points.
bool within_margin(const RigidBody& a, const RigidBody& b, double distance, double travel_a, double travel_b);

/// Writes the contact of a pair overlaps() accepted into `contact`, which must be a default
/// Contact; same result as collide(). Returns false when the pair does not touch after all:
/// for a pair with a box, overlaps() only compares bounding spheres and the full
/// separating-axis test runs here. `reach` (m, 0 by default) is the reach of the pair's
/// speculative points for a pair with a box (box_detection.hpp); two spheres, or a sphere and
/// a plane, are written whatever their distance, the gap as a negative depth.
bool write_contact(const RigidBody& a, std::uint32_t index_a, const RigidBody& b, std::uint32_t index_b, Contact& contact,
                   double reach = 0.0);

}  // namespace workbook
