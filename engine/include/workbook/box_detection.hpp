#pragma once
/// \file
/// Narrow-phase detection for boxes: box-plane, sphere-box and box-box (separating axes and
/// face clipping). Each function writes the contact in place and returns whether the bodies
/// overlap; like the sphere tests, touching without overlap is no contact, except between two
/// boxes: boxes that touch to within rounding (1e-9 of the larger box) are in contact, and a
/// corner of a face resting on a face touches it while it lies on it to within
/// tolerances::resting_corner (a point of depth 0), so that a box resting on a box is held at
/// all four corners.
///
/// Every contact point sits halfway between the two surfaces it joins (as for spheres), so a
/// point may lie outside either body by at most half its depth. A pair has at most
/// max_contact_points points: a face on a face or a plane gives up to four, an edge two, a
/// corner or crossing edges one. The normal is a unit vector from body 2 towards body 1, and
/// Contact::penetration is the overlap of the two bodies' shadows on that normal, which is how
/// far body 1 must move along it to separate them (at least the depth of every point).
///
/// `reach` (m, 0 by default) asks for speculative points as well
/// (ContactSolverSettings::speculative_distance): where the bodies are apart by less than it,
/// the points they would touch at first, each with its gap as a negative depth, as for two
/// spheres. The function then returns true for a pair apart by less than the reach.

#include <cstdint>

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

/// A box (body 1) against a plane (body 2): the box corners behind the plane, at most four
/// (the deepest and the widest spread), each with its depth below the plane.
bool collide_box_plane(const RigidBody& box, const RigidBody& plane, Contact& out, double reach = 0.0);

/// A sphere (body 1) against a box (body 2): one point, between the sphere's deepest point and
/// the box surface nearest to its centre (or, for a centre inside the box, the nearest face).
bool collide_sphere_box(const RigidBody& sphere, const RigidBody& box, Contact& out, double reach = 0.0);

/// Two boxes, `a` as body 1 and `b` as body 2. The separating-axis test over the 15 candidate
/// axes (three face normals of each box and the nine cross products of their edges) finds the
/// axis of least overlap. For a face axis, the face of the other box that turns most towards it
/// is clipped against the side planes of the reference face and the clipped corners below that
/// face become the points (at most four kept); for an edge axis, one point between the two
/// edges. Swapping a and b flips the normal and keeps the points.
bool collide_box_box(const RigidBody& a, const RigidBody& b, Contact& out, double reach = 0.0);

/// The point of `box` (its orientation and half extents, its centre at `centre`, which may
/// differ from its position) nearest to `point`: `point` itself when inside.
Vector3 nearest_point_on_box(const RigidBody& box, const Vector3& centre, const Vector3& point);

/// Any pair with at least one box, dispatched on the shapes: writes the contact with its body
/// indices and returns true when they overlap, false otherwise (also for a pair without a box).
/// A plane is always body 2, as in collide(); otherwise `a` is body 1.
bool collide_with_box(const RigidBody& a, std::uint32_t index_a, const RigidBody& b, std::uint32_t index_b,
                      Contact& out, double reach = 0.0);

}  // namespace workbook
