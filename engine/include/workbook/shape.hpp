#pragma once
/// \file
/// Collision shapes. One plain struct with a kind tag keeps bodies contiguous and trivially
/// copyable; detection dispatches on the pair of kinds.

#include <cstdint>

#include "workbook/vector3.hpp"

namespace workbook {

/// Which kind of geometry a Shape holds.
enum class ShapeKind : std::uint8_t {
    sphere,  ///< a ball (a circle when the scene is planar)
    plane,   ///< an infinite plane through the body's position: walls and ground
    box,     ///< a cuboid given by its half extents (chapter 4 on); detection reports up to four points for it
};

/// The geometry of a body, in the body's own frame.
struct Shape {
    ShapeKind kind = ShapeKind::sphere;  ///< which of the fields below apply
    double radius = 0.0;            ///< sphere only
    Vector3 normal{0.0, 1.0, 0.0};  ///< plane only: unit normal in body space, pointing out of the solid side
    Vector3 half_extents{};         ///< box only

    /// A sphere of the given radius, m.
    static constexpr Shape sphere(double radius) { return {ShapeKind::sphere, radius, {}, {}}; }
    /// A plane with the given unit normal (body space).
    static constexpr Shape plane(const Vector3& unit_normal) { return {ShapeKind::plane, 0.0, unit_normal, {}}; }
    /// A box with the given half extents, m.
    static constexpr Shape box(const Vector3& half_extents) { return {ShapeKind::box, 0.0, {}, half_extents}; }
};

/// Lower-case name used in scene files and messages ("sphere", "plane", "box").
constexpr const char* to_string(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::sphere: return "sphere";
        case ShapeKind::plane: return "plane";
        case ShapeKind::box: return "box";
    }
    return "unknown";
}

}  // namespace workbook
