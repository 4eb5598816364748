#include "workbook/detection.hpp"

#include <utility>

namespace workbook {

std::optional<Contact> collide_spheres(const RigidBody& sphere1, const RigidBody& sphere2) {
    const Vector3 offset = sphere1.position - sphere2.position;
    const double radii = sphere1.shape.radius + sphere2.shape.radius;
    const double distance_squared = length_squared(offset);
    if (distance_squared >= radii * radii) return std::nullopt;

    const double distance = std::sqrt(distance_squared);
    Contact contact;
    contact.normal = distance > 0.0 ? offset / distance : coincident_centres_normal;
    const double overlap = radii - distance;
    // The point halfway between the two deepest surface points, so neither body is favoured.
    const Vector3 point = sphere2.position + contact.normal * (sphere2.shape.radius - overlap / 2.0);
    contact.add_point(point, overlap);
    return contact;
}

std::optional<Contact> collide_sphere_plane(const RigidBody& sphere, const RigidBody& plane) {
    const Vector3 normal = rotate(plane.orientation, plane.shape.normal);
    const double height = dot(sphere.position - plane.position, normal);
    const double overlap = sphere.shape.radius - height;
    if (overlap <= 0.0) return std::nullopt;

    Contact contact;
    contact.normal = normal;
    const Vector3 point = sphere.position - normal * ((sphere.shape.radius + height) / 2.0);
    contact.add_point(point, overlap);
    return contact;
}

std::optional<Contact> collide(const RigidBody& a, std::uint32_t index_a, const RigidBody& b, std::uint32_t index_b) {
    std::optional<Contact> contact;
    const ShapeKind ka = a.shape.kind;
    const ShapeKind kb = b.shape.kind;
    if (ka == ShapeKind::sphere && kb == ShapeKind::sphere) {
        contact = collide_spheres(a, b);
    } else if (ka == ShapeKind::sphere && kb == ShapeKind::plane) {
        contact = collide_sphere_plane(a, b);
    } else if (ka == ShapeKind::plane && kb == ShapeKind::sphere) {
        contact = collide_sphere_plane(b, a);
        std::swap(index_a, index_b);
    }
    // Plane-plane pairs are two immovable bodies and never need a response; boxes arrive
    // with chapter 4 and are rejected by the scene loader until then.
    if (contact) {
        contact->body1 = index_a;
        contact->body2 = index_b;
    }
    return contact;
}

}  // namespace workbook
