#include "workbook/sleeping.hpp"

#include <algorithm>
#include <cmath>

namespace workbook {

namespace {

/// How far the body's surface reaches from its centre: a spin w moves it at up to |w| times this.
double reach(const RigidBody& body) {
    switch (body.shape.kind) {
        case ShapeKind::sphere: return body.shape.radius;
        case ShapeKind::box: return length(body.shape.half_extents);
        case ShapeKind::plane: return 0.0;
    }
    return 0.0;
}

/// A contact with an immovable body that moves (a kinematic one) keeps its partner awake.
bool moving_kinematic(const RigidBody& body) {
    return body.is_immovable() && (body.velocity != Vector3{} || body.angular_velocity != Vector3{});
}

}  // namespace

void Sleeping::size_for(std::size_t count) {
    if (parent_.size() == count) return;
    parent_.assign(count, 0);
    still_.assign(count, 0.0);
    asleep_.assign(count, 0);
    island_awake_.assign(count, 0);
    island_still_.assign(count, 0.0);
    woken_.assign(count, 0);
    woken_count_ = 0;
    sleeping_ = 0;
}

std::uint32_t Sleeping::root(std::uint32_t i) {
    while (parent_[i] != i) {
        parent_[i] = parent_[parent_[i]];  // path halving
        i = parent_[i];
    }
    return i;
}

void Sleeping::wake_touched(std::span<RigidBody> bodies, std::span<const Contact> contacts) {
    size_for(bodies.size());
    for (std::uint32_t i = 0; i < parent_.size(); ++i) parent_[i] = i;
    for (const Contact& contact : contacts) {
        if (bodies[contact.body1].is_immovable() || bodies[contact.body2].is_immovable()) continue;
        const std::uint32_t a = root(contact.body1), b = root(contact.body2);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }
    if (woken_count_ > 0) {
        std::fill(woken_.begin(), woken_.end(), std::uint8_t{0});
        woken_count_ = 0;
    }
    if (sleeping_ == 0) return;
    std::fill(island_awake_.begin(), island_awake_.end(), std::uint8_t{0});
    for (std::uint32_t i = 0; i < parent_.size(); ++i)
        if (!bodies[i].is_immovable() && asleep_[i] == 0) island_awake_[root(i)] = 1;
    for (const Contact& contact : contacts) {
        if (moving_kinematic(bodies[contact.body2]) && !bodies[contact.body1].is_immovable()) island_awake_[root(contact.body1)] = 1;
        if (moving_kinematic(bodies[contact.body1]) && !bodies[contact.body2].is_immovable()) island_awake_[root(contact.body2)] = 1;
    }
    for (std::uint32_t i = 0; i < parent_.size(); ++i) {
        if (asleep_[i] != 0 && island_awake_[root(i)] != 0) {
            asleep_[i] = 0;
            still_[i] = 0.0;
            --sleeping_;
            woken_[i] = 1;
            ++woken_count_;
        }
    }
}

void Sleeping::fall_asleep(std::span<RigidBody> bodies, const ContactSolverSettings& settings, double dt) {
    size_for(bodies.size());
    std::fill(island_still_.begin(), island_still_.end(), settings.sleep_time);
    for (std::uint32_t i = 0; i < parent_.size(); ++i) {
        const RigidBody& body = bodies[i];
        if (body.is_immovable() || asleep_[i] != 0) continue;
        const bool still = length(body.velocity) <= settings.sleep_speed &&
                           length(body.angular_velocity) * reach(body) <= settings.sleep_speed;
        still_[i] = still ? still_[i] + dt : 0.0;
        double& island = island_still_[root(i)];
        island = std::min(island, still_[i]);
    }
    for (std::uint32_t i = 0; i < parent_.size(); ++i) {
        RigidBody& body = bodies[i];
        if (body.is_immovable() || asleep_[i] != 0 || !(island_still_[root(i)] >= settings.sleep_time)) continue;
        asleep_[i] = 1;
        body.velocity = body.angular_velocity = Vector3{};
        ++sleeping_;
    }
}

void Sleeping::wake(std::size_t i) {
    if (!asleep(i)) return;
    asleep_[i] = 0;
    still_[i] = 0.0;
    --sleeping_;
}

void Sleeping::wake_all() {
    std::fill(asleep_.begin(), asleep_.end(), std::uint8_t{0});
    std::fill(still_.begin(), still_.end(), 0.0);
    sleeping_ = 0;
}

}  // namespace workbook
