#include "workbook/rigid_body.hpp"

namespace workbook {

RigidBody make_sphere(double mass, double radius, const Vector3& position, const Vector3& velocity) {
    RigidBody body;
    body.inverse_mass = 1.0 / mass;
    body.inertia_body = solid_sphere_inertia(mass, radius);
    body.position = position;
    body.velocity = velocity;
    body.shape = Shape::sphere(radius);
    body.update_world_inertia();
    return body;
}

RigidBody make_immovable_plane(const Vector3& unit_normal, const Vector3& point) {
    RigidBody body;
    body.inverse_mass = 0.0;
    body.inertia_body = Matrix3::zero();
    body.position = point;
    body.shape = Shape::plane(unit_normal);
    body.update_world_inertia();
    return body;
}

RigidBody make_immovable_sphere(double radius, const Vector3& position) {
    RigidBody body;
    body.inverse_mass = 0.0;
    body.inertia_body = Matrix3::zero();
    body.position = position;
    body.shape = Shape::sphere(radius);
    body.update_world_inertia();
    return body;
}

RigidBody make_box(double mass, const Vector3& half_extents, const Vector3& position, const Quaternion& orientation,
                   const Vector3& velocity) {
    RigidBody body;
    body.inverse_mass = 1.0 / mass;
    body.inertia_body = solid_box_inertia(mass, half_extents);
    body.position = position;
    body.orientation = orientation;
    body.velocity = velocity;
    body.shape = Shape::box(half_extents);
    body.update_world_inertia();
    return body;
}

}  // namespace workbook
