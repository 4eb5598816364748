#include "workbook/world.hpp"

#include <utility>

#include "workbook/detection.hpp"

namespace workbook {

namespace {

/// The largest number of contacts a step can produce: one per pair with a movable body.
std::size_t worst_case_contacts(std::span<const RigidBody> bodies) {
    std::size_t movable = 0;
    for (const RigidBody& body : bodies)
        if (!body.is_immovable()) ++movable;
    const std::size_t immovable = bodies.size() - movable;
    const std::size_t movable_pairs = movable > 0 ? movable * (movable - 1) / 2 : 0;
    return movable_pairs + movable * immovable;
}

}  // namespace

World::World(std::vector<RigidBody> bodies, WorldSettings settings, ResponseModel model)
    : bodies_(std::move(bodies)), settings_(settings), model_(model) {
    for (RigidBody& body : bodies_) body.update_world_inertia();
    contacts_.reserve(worst_case_contacts(bodies_));
}

void World::step() {
    integrate();
    detect();
    respond();
    correct();
    time_ += settings_.time_step;
}

void World::integrate() {
    const double dt = settings_.time_step;
    const Vector3 gravity_kick = settings_.gravity * dt;
    for (RigidBody& body : bodies_) {
        if (body.is_immovable()) continue;
        if (settings_.integrator == Integrator::semi_implicit_euler) {
            body.velocity += gravity_kick;
            body.position += body.velocity * dt;
        } else {
            body.position += body.velocity * dt;
            body.velocity += gravity_kick;
        }
        if (body.angular_velocity == Vector3{}) continue;
        body.orientation = workbook::integrate(body.orientation, body.angular_velocity, dt);
        body.update_world_inertia();
    }
}

void World::detect() {
    contacts_.clear();
    const auto count = static_cast<std::uint32_t>(bodies_.size());
    for (std::uint32_t i = 0; i < count; ++i) {
        for (std::uint32_t j = i + 1; j < count; ++j) {
            if (bodies_[i].is_immovable() && bodies_[j].is_immovable()) continue;
            if (auto contact = collide(bodies_[i], i, bodies_[j], j)) contacts_.push_back(*contact);
        }
    }
}

void World::respond() {
    response_energy_change_ = 0.0;
    if (model_.respond == nullptr) return;
    for (const Contact& contact : contacts_) {
        RigidBody& body1 = bodies_[contact.body1];
        RigidBody& body2 = bodies_[contact.body2];
        const double before = kinetic_energy(body1) + kinetic_energy(body2);
        model_.respond(body1, body2, contact);
        response_energy_change_ += kinetic_energy(body1) + kinetic_energy(body2) - before;
    }
}

void World::correct() {
    if (model_.correct == nullptr) return;
    for (const Contact& contact : contacts_) model_.correct(bodies_[contact.body1], bodies_[contact.body2], contact);
}

Probes World::probes() const {
    Probes p = measure(bodies_, settings_.gravity);
    p.time = time_;
    p.response_energy_change = response_energy_change_;
    p.contacts = static_cast<int>(contacts_.size());
    return p;
}

}  // namespace workbook
