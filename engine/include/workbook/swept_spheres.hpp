#pragma once
/// \file
/// The swept test of discrete timing: a sphere that moved further than the smallest radius in
/// a step is traced along its path, so that it cannot pass through another body unseen.

#include <cstdint>
#include <vector>

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"
#include "workbook/vector3.hpp"

namespace workbook {

class World;

/// Where `body` started the step, undoing what integrate() did: x_end - v_end dt + g c dt^2, with
/// `gravity_term` = g c dt^2 and c = 1 - k (0 for semi-implicit Euler, 1/2 for
/// exact-under-gravity, 1 for explicit Euler). Immovable bodies stay where they are.
inline Vector3 start_of_step(const RigidBody& body, double dt, const Vector3& gravity_term) {
    if (body.is_immovable()) return body.position;
    return body.position - body.velocity * dt + gravity_term;
}

/// What sweep_fast_spheres() keeps between steps, so that a warm step allocates nothing.
struct SweepScratch {
    std::vector<Vector3> starts;         ///< where each body started the step, by body index
    std::vector<std::uint32_t> moved;    ///< spheres moved back this step, in index order
    std::vector<std::uint8_t> is_moved;  ///< 1 for a sphere in `moved`, by body index
    std::vector<Contact> found;          ///< touching contacts found this step, in the order found
};

/// After detect(): every sphere that moved further than the smallest radius in the world is
/// traced from where it started the step to where it ended, in index order; if it went through
/// another sphere, or its centre ended behind a plane, it goes back to the moment of touching
/// and that touch replaces its contacts. A sphere moved back keeps its start: later spheres
/// are traced against the part of its path it did travel. With the grid of this step's
/// detect(), only the candidates the broad phase found are tried, with the same result as
/// trying every body.
void sweep_fast_spheres(World& world);

}  // namespace workbook
