#pragma once
/// \file
/// The collision data detection hands to a responder.

#include <array>
#include <cstddef>
#include <cstdint>

#include "workbook/vector3.hpp"

namespace workbook {

/// Most points one pair can touch at: a box face on a plane or on another face gives four.
inline constexpr std::size_t max_contact_points = 4;

/// One point where two bodies touch.
struct ContactPoint {
    Vector3 position{};        ///< world position of the contact, m
    /// overlap measured along the contact normal at this point, m (>= 0; negative only for a
    /// speculative contact, ContactSolverSettings::speculative_distance: the pair is apart by that much)
    double penetration = 0.0;
};

/// Everything a responder needs about one overlapping pair.
///
/// Convention, used everywhere in the workbook: `normal` is a unit vector pointing **from
/// body 2 towards body 1**. Pushing body 1 along +normal and body 2 along -normal separates
/// them, and the pair is approaching exactly when dot(v1 - v2, normal) < 0.
struct Contact {
    std::uint32_t body1 = 0;  ///< index of body 1 in the world
    std::uint32_t body2 = 0;  ///< index of body 2 in the world
    Vector3 normal{1.0, 0.0, 0.0};  ///< unit vector from body 2 towards body 1
    std::array<ContactPoint, max_contact_points> points{};  ///< the first `point_count` entries are valid
    std::uint8_t point_count = 0;  ///< number of valid entries in `points`
    double penetration = 0.0;  ///< overlap along the normal, m: at least every point's depth and at least 0 (for a box pair, the overlap of the two shadows on the normal)

    /// Appends a point and keeps `penetration` the deepest one; ignores points past the capacity.
    constexpr void add_point(const Vector3& position, double depth) {
        if (point_count == max_contact_points) return;
        points[point_count++] = {position, depth};
        if (depth > penetration) penetration = depth;
    }
};

}  // namespace workbook
