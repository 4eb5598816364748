#pragma once
/// \file
/// One number for the whole state of a world after a step: every body's position,
/// orientation, velocity and angular velocity, and every contact (bodies, normal, points,
/// depths) in order. Two runs with the same hash after every step took the same path.
///
/// Doubles are hashed by their bits, with one exception: -0.0 and +0.0 hash alike. They are
/// the same number (==), and adding a zero gravity kick (v + 0) turns a -0 velocity into +0,
/// a difference no later arithmetic can see; every other bit counts.

#include <bit>
#include <cstdint>

#include "workbook/world.hpp"

namespace workbook::testing {

class StateHash {
public:
    void add(std::uint64_t value) {
        for (int i = 0; i < 8; ++i) {
            hash_ ^= (value >> (8 * i)) & 0xFFu;
            hash_ *= 0x100000001B3u;  // FNV-1a
        }
    }
    void add(double value) { add(value == 0.0 ? std::uint64_t{0} : std::bit_cast<std::uint64_t>(value)); }
    void add(const Vector3& v) {
        add(v.x);
        add(v.y);
        add(v.z);
    }
    [[nodiscard]] std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 0xCBF29CE484222325u;
};

/// The hash of the world's bodies and of the contacts its last detect() found.
inline std::uint64_t state_hash(const World& world) {
    StateHash h;
    for (const RigidBody& body : world.bodies()) {
        h.add(body.position);
        h.add(body.velocity);
        h.add(body.angular_velocity);
        h.add(body.orientation.w);
        h.add(Vector3{body.orientation.x, body.orientation.y, body.orientation.z});
    }
    for (const Contact& contact : world.contacts()) {
        h.add(std::uint64_t{contact.body1} << 32 | contact.body2);
        h.add(contact.normal);
        h.add(contact.penetration);
        h.add(std::uint64_t{contact.point_count});
        for (std::uint8_t i = 0; i < contact.point_count; ++i) {
            h.add(contact.points[i].position);
            h.add(contact.points[i].penetration);
        }
    }
    return h.value();
}

}  // namespace workbook::testing
