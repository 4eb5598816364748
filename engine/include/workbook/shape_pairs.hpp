#pragma once
/// \file
/// The pairs of shapes, as one closed list, and what each stage does with each pair. Every
/// dispatch on two shapes goes through pair_of() and a switch over ShapePair with no default:
/// a new ShapeKind fails to compile in pair_of() until it is paired with every kind, and a new
/// ShapePair fails to compile in every stage until that stage says what it does with it
/// (GCC and Clang: -Wswitch, an error with -Werror; MSVC: C4062 at level 4).
///
/// | pair          | detect (detection.cpp)          | swept test (swept_spheres.cpp)   | event timing (event_timing.cpp)           |
/// |---------------|---------------------------------|----------------------------------|-------------------------------------------|
/// | sphere-sphere | closed form                     | traced (closed form)             | closed form (quartic when one is pinned)  |
/// | sphere-plane  | closed form                     | traced (centre behind the plane) | closed form                               |
/// | sphere-box    | box_detection.cpp               | traced (convex distance search)  | sampled and bisected (box not spinning)   |
/// | plane-plane   | never (both immovable)          | -                                | never                                     |
/// | plane-box     | box_detection.cpp               | boxes are not traced             | closed form (box not spinning)            |
/// | box-box       | box_detection.cpp               | boxes are not traced             | left to the back-stop                     |

#include <cstdint>

#include "workbook/shape.hpp"

namespace workbook {

/// An unordered pair of shape kinds.
enum class ShapePair : std::uint8_t { sphere_sphere, sphere_plane, sphere_box, plane_plane, plane_box, box_box };

/// The pair of kinds a and b, in either order.
constexpr ShapePair pair_of(ShapeKind a, ShapeKind b) {
    switch (a) {
        case ShapeKind::sphere:
            switch (b) {
                case ShapeKind::sphere: return ShapePair::sphere_sphere;
                case ShapeKind::plane: return ShapePair::sphere_plane;
                case ShapeKind::box: return ShapePair::sphere_box;
            }
            break;
        case ShapeKind::plane:
            switch (b) {
                case ShapeKind::sphere: return ShapePair::sphere_plane;
                case ShapeKind::plane: return ShapePair::plane_plane;
                case ShapeKind::box: return ShapePair::plane_box;
            }
            break;
        case ShapeKind::box:
            switch (b) {
                case ShapeKind::sphere: return ShapePair::sphere_box;
                case ShapeKind::plane: return ShapePair::plane_box;
                case ShapeKind::box: return ShapePair::box_box;
            }
            break;
    }
    return ShapePair::plane_plane;  // not reached for valid kinds
}

/// "sphere-box" and so on, for messages.
constexpr const char* to_string(ShapePair pair) {
    switch (pair) {
        case ShapePair::sphere_sphere: return "sphere-sphere";
        case ShapePair::sphere_plane: return "sphere-plane";
        case ShapePair::sphere_box: return "sphere-box";
        case ShapePair::plane_plane: return "plane-plane";
        case ShapePair::plane_box: return "plane-box";
        case ShapePair::box_box: return "box-box";
    }
    return "unknown";
}

}  // namespace workbook
