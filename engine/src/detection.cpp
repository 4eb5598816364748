#include "workbook/detection.hpp"
#include "workbook/shape_pairs.hpp"

#include <utility>

#include "workbook/box_detection.hpp"
#include "workbook/broad_phase.hpp"

namespace workbook {

bool spheres_overlap(const Vector3& centre1, double radius1, const Vector3& centre2, double radius2) {
    const double radii = radius1 + radius2;
    // Written as "not apart" so that a NaN position still yields a (NaN) contact, as it always
    // has: a broken state shows in the contacts instead of vanishing from them.
    return !(length_squared(centre1 - centre2) >= radii * radii);
}

void write_spheres(const Vector3& centre1, double radius1, const Vector3& centre2, double radius2, Contact& contact) {
    const Vector3 offset = centre1 - centre2;
    const double radii = radius1 + radius2;
    const double distance = std::sqrt(length_squared(offset));
    contact.normal = distance > 0.0 ? offset / distance : coincident_centres_normal;
    const double overlap = radii - distance;
    // The point halfway between the two deepest surface points, so neither body is favoured.
    const Vector3 point = centre2 + contact.normal * (radius2 - overlap / 2.0);
    contact.add_point(point, overlap);
}

bool sphere_plane_overlap(const Vector3& centre, double radius, const Vector3& point, const Vector3& normal) {
    return !(radius - dot(centre - point, normal) <= 0.0);
}

void write_sphere_plane(const Vector3& centre, double radius, const Vector3& point, const Vector3& normal, Contact& contact) {
    // Height of the centre above the plane.
    const double height = dot(centre - point, normal);
    contact.normal = normal;
    const Vector3 at = centre - normal * ((radius + height) / 2.0);
    contact.add_point(at, radius - height);
}

namespace {

// Each shape pair has one yes/no test and one writer. The writer repeats the test's
// arithmetic (the same expressions, so the same bits) instead of receiving it, which keeps
// overlaps() free of any state and the writer callable on its own.

bool spheres_overlap(const RigidBody& sphere1, const RigidBody& sphere2) {
    return spheres_overlap(sphere1.position, sphere1.shape.radius, sphere2.position, sphere2.shape.radius);
}

void write_spheres(const RigidBody& sphere1, const RigidBody& sphere2, Contact& contact) {
    write_spheres(sphere1.position, sphere1.shape.radius, sphere2.position, sphere2.shape.radius, contact);
}

/// Whether a pair with a box can touch at all: its bounding sphere (workbook::bounding_radius)
/// reaches the other body's, or the plane, or comes within `gap` of it. Conservative; the box
/// test decides.
bool bounding_spheres_may_touch(const RigidBody& a, const RigidBody& b, double gap = 0.0) {
    if (a.shape.kind == ShapeKind::plane) return bounding_spheres_may_touch(b, a, gap);
    if (b.shape.kind == ShapeKind::plane) {
        const Vector3 normal = rotate(b.orientation, b.shape.normal);
        return !(dot(a.position - b.position, normal) > bounding_radius(a) + gap);
    }
    const double reach = bounding_radius(a) + bounding_radius(b) + gap;
    return !(length_squared(a.position - b.position) > reach * reach);
}

bool sphere_plane_overlap(const RigidBody& sphere, const RigidBody& plane) {
    return sphere_plane_overlap(sphere.position, sphere.shape.radius, plane.position, rotate(plane.orientation, plane.shape.normal));
}

void write_sphere_plane(const RigidBody& sphere, const RigidBody& plane, Contact& contact) {
    write_sphere_plane(sphere.position, sphere.shape.radius, plane.position, rotate(plane.orientation, plane.shape.normal),
                       contact);
}

}  // namespace

std::optional<Contact> collide_spheres(const RigidBody& sphere1, const RigidBody& sphere2) {
    if (!spheres_overlap(sphere1, sphere2)) return std::nullopt;
    Contact contact;
    write_spheres(sphere1, sphere2, contact);
    return contact;
}

std::optional<Contact> collide_sphere_plane(const RigidBody& sphere, const RigidBody& plane) {
    if (!sphere_plane_overlap(sphere, plane)) return std::nullopt;
    Contact contact;
    write_sphere_plane(sphere, plane, contact);
    return contact;
}

bool overlaps(const RigidBody& a, const RigidBody& b) {
    switch (pair_of(a.shape.kind, b.shape.kind)) {
        case ShapePair::sphere_sphere: return spheres_overlap(a, b);
        case ShapePair::sphere_plane:
            return a.shape.kind == ShapeKind::sphere ? sphere_plane_overlap(a, b) : sphere_plane_overlap(b, a);
        // A pair with a box is decided in full by the separating-axis test of write_contact()
        // (box_detection.cpp); here only its bounding spheres, so most far pairs stop cheaply.
        case ShapePair::sphere_box:
        case ShapePair::plane_box:
        case ShapePair::box_box: return bounding_spheres_may_touch(a, b);
        // Plane-plane pairs are two immovable bodies and never need a response.
        case ShapePair::plane_plane: return false;
    }
    return false;
}

double speculative_reach(const RigidBody& a, const RigidBody& b, double distance, double travel_a, double travel_b) {
    // A plane stays where it is: a body that the solve stops goes back at most to where it
    // started the step, which was clear of the plane, so only the distance.
    if (a.shape.kind == ShapeKind::plane || b.shape.kind == ShapeKind::plane) return distance;
    return speculative_reach(distance, travel_a, travel_b);
}

bool within_margin(const RigidBody& a, const RigidBody& b, double distance, double travel_a, double travel_b) {
    const double reach = speculative_reach(a, b, distance, travel_a, travel_b);
    switch (pair_of(a.shape.kind, b.shape.kind)) {
        case ShapePair::sphere_sphere: return spheres_overlap(a.position, a.shape.radius + reach, b.position, b.shape.radius);
        case ShapePair::sphere_plane: {
            const RigidBody& sphere = a.shape.kind == ShapeKind::sphere ? a : b;
            const RigidBody& plane = a.shape.kind == ShapeKind::sphere ? b : a;
            return sphere_plane_overlap(sphere.position, sphere.shape.radius + reach, plane.position,
                                        rotate(plane.orientation, plane.shape.normal));
        }
        // The box test decides; here only whether the bounding spheres come within reach.
        case ShapePair::sphere_box:
        case ShapePair::box_box:
        case ShapePair::plane_box: return bounding_spheres_may_touch(a, b, reach);
        case ShapePair::plane_plane: return false;
    }
    return false;
}

bool write_contact(const RigidBody& a, std::uint32_t index_a, const RigidBody& b, std::uint32_t index_b, Contact& contact,
                   double reach) {
    switch (pair_of(a.shape.kind, b.shape.kind)) {
        case ShapePair::sphere_box:
        case ShapePair::plane_box:
        case ShapePair::box_box: return collide_with_box(a, index_a, b, index_b, contact, reach);
        case ShapePair::sphere_plane:
            // The sphere is body 1, so that the normal points from the plane to it.
            if (a.shape.kind == ShapeKind::plane) {
                write_sphere_plane(b, a, contact);
                std::swap(index_a, index_b);
            } else {
                write_sphere_plane(a, b, contact);
            }
            break;
        case ShapePair::sphere_sphere: write_spheres(a, b, contact); break;
        case ShapePair::plane_plane: return false;  // never overlaps()
    }
    contact.body1 = index_a;
    contact.body2 = index_b;
    return true;
}

std::optional<Contact> collide(const RigidBody& a, std::uint32_t index_a, const RigidBody& b, std::uint32_t index_b) {
    if (!overlaps(a, b)) return std::nullopt;
    Contact contact;
    if (!write_contact(a, index_a, b, index_b, contact)) return std::nullopt;
    return contact;
}

}  // namespace workbook
