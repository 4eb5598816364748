#pragma once
/// \file
/// The broad phase: which pairs of bodies are worth handing to the narrow phase.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "workbook/rigid_body.hpp"

namespace workbook {

/// Two body indices, `first < second`.
struct BodyPair {
    std::uint32_t first;   ///< the smaller index
    std::uint32_t second;  ///< the larger index
};

/// A bounded body as the broad phase's grid loop reads it: 40 bytes instead of a whole
/// RigidBody. (Outside BroadPhase so that the API reference has no private nested class.)
struct GridProxy {
    double x;              ///< centre, x, m
    double y;              ///< centre, y, m
    double z;              ///< centre, z, m
    double radius;         ///< bounding radius, m
    std::uint32_t index;   ///< body index
    bool movable;          ///< false for an immovable body
};

/// A uniform grid over the bodies' bounding spheres, rebuilt every step.
///
/// Why a grid and not sort-and-sweep: for the even densities the workbook's scenes have (a
/// gas, a pile, a few bodies) a grid whose cells are one diameter wide finds each body's
/// neighbours in the 3 x 3 x 3 cells around it, a constant amount of work per body, so the
/// whole pass is linear in N. Sort-and-sweep along one axis finds every body whose extent
/// overlaps along that axis: in the 2D gas of issue 12 that is a strip through the whole box,
/// about N * 2 d / L bodies, so its cost grows as N^1.5 (measured with bench/stages.cpp:
/// at N = 100,000 the strip holds about 100 bodies against the grid's 0.5 per cell).
///
/// Planes are unbounded and stay out of the grid: each body is paired with each plane its
/// bounding sphere reaches (a body in the middle of the gas reaches none of the four walls).
/// The pairs come out sorted by (first, second), the order in which testing every pair
/// visits them, so that sequential responders see contacts in the same order and the
/// results are bit-identical to testing all pairs.
class BroadPhase {
public:
    /// Replaces `pairs` with every pair whose bounding spheres overlap (a conservative test:
    /// the narrow phase decides), plus every pair with a plane, leaving out pairs of two
    /// immovable bodies unless `immovable_pairs`. Allocates only when the scene grew.
    void find_pairs(std::span<const RigidBody> bodies, std::vector<BodyPair>& pairs, bool immovable_pairs = false);

    /// Every pair in index order, without a grid: what find_pairs() falls back to for
    /// bodies at non-finite positions, and what the world uses for a handful of bodies.
    static void all_pairs(std::span<const RigidBody> bodies, std::vector<BodyPair>& pairs, bool immovable_pairs = false);

private:
    using Proxy = GridProxy;
    std::vector<Proxy> proxies_;            ///< bounded bodies, in index order
    std::vector<std::uint32_t> unbounded_;  ///< planes, in index order
    std::vector<Vector3> plane_normals_;    ///< world normal of each plane in unbounded_
    std::vector<std::uint32_t> cell_of_;    ///< grid cell of each proxy
    std::vector<std::uint32_t> cell_start_; ///< first entry of each cell in by_cell_ (counting sort)
    std::vector<Proxy> by_cell_;            ///< the proxies grouped by cell, each cell in index order
    std::vector<std::uint32_t> candidates_; ///< one body's partners, sorted before they are emitted
};

/// Radius of a sphere around the body's position that holds its whole shape; infinite for a plane.
double bounding_radius(const RigidBody& body);

}  // namespace workbook
