#pragma once
/// \file
/// The swept test of discrete timing: a sphere that moved further than the smallest radius in
/// a step is traced along its path against spheres, planes and boxes, so that it cannot pass
/// through another body unseen. Boxes themselves are not traced: a fast box can pass through a
/// thin body between two steps (docs/scene-format.md says so where scenes are described).

#include <cstdint>
#include <span>
#include <vector>

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"
#include "workbook/tolerances.hpp"
#include "workbook/vector3.hpp"

namespace workbook {

class BroadPhase;
struct ProxySet;

/// Where `body` started the step, undoing what integrate() did: x_end - v_end dt + g c dt^2, with
/// `gravity_term` = g c dt^2 and c = 1 - k (0 for semi-implicit Euler, 1/2 for
/// exact-under-gravity, 1 for explicit Euler). Immovable bodies stay where they are.
inline Vector3 start_of_step(const RigidBody& body, double dt, const Vector3& gravity_term) {
    if (body.is_immovable()) return body.position;
    return body.position - body.velocity * dt + gravity_term;
}

/// Whether two spheres' straight paths over the step (starts a0, b0, ends a1, b1, radii ra, rb)
/// may touch as sweep_fast_spheres() counts a touch: never false when it would find one, and
/// cheap (no square root, no division). With d = a0 - b0 and u the relative travel, the
/// distance |d + s u| is least at s* = -d.u / u.u; a touch there needs the pair to approach
/// (d.u < 0, the swept test's own comparison on the same numbers), the line of relative motion
/// to pass within R = ra + rb (|d|^2 |u|^2 - (d.u)^2 <= R^2 |u|^2), and the pair to be apart at
/// the end (the test leaves overlaps at the end to detection), which, with both roots of
/// |d + s u| = R before s = 1, puts s* before 1 as well. Each comparison has room for rounding.
/// The same whichever sphere is `a`.
inline bool spheres_may_touch(const Vector3& a1, const Vector3& a0, double ra, const Vector3& b1, const Vector3& b0,
                              double rb) {
    const Vector3 d = a0 - b0;
    const Vector3 u = (a1 - a0) - (b1 - b0);
    const double approach = dot(d, u);
    if (!(approach < 0.0)) return false;
    const double radii = ra + rb;
    const double rr = radii * radii;
    const double uu = length_squared(u);
    // s* < 1. A pair that can touch started within R + |u|, so |d.u| <= R |u| + u.u and its
    // rounding stays far below the slack times (2 u.u + R^2) >= slack (u.u + R |u|).
    constexpr double slack = tolerances::may_touch_slack;
    if (-approach > uu + slack * (2.0 * uu + rr)) return false;
    // Apart at the end.
    if (length_squared(a1 - b1) < rr * (1.0 - slack)) return false;
    const double far = length_squared(d) * uu;
    return far - approach * approach <= rr * uu + slack * far;
}

/// What sweep_fast_spheres() keeps between steps, so that a warm step allocates nothing.
struct SweepScratch {
    std::vector<Vector3> starts;         ///< without the grid: where each body started the step
    std::vector<std::uint32_t> moved;    ///< spheres moved back this step, in index order
    std::vector<std::uint8_t> is_moved;  ///< 1 for a sphere in `moved`, by body index
    std::vector<Contact> found;          ///< touching contacts found this step, one per moved sphere
    std::vector<std::uint32_t> candidates;  ///< bodies a moved sphere is detected again against
    std::vector<std::uint32_t> boxes;    ///< the boxes, which the swept test's partners leave out
};

/// The grid of this step's detect(), when it used one with a swept set: its proxies (the
/// swept test moves a sphere's proxy with the sphere) and the broad phase that found the swept
/// test's partners. Both null without a grid.
struct SweepGrid {
    ProxySet* proxies = nullptr;                ///< the proxies the grid was filled from; moved with a moved sphere
    const BroadPhase* broad_phase = nullptr;  ///< the broad phase whose sweep_partners() the swept test reads
};

/// The swept test, after detect() has filled `contacts`: every sphere that moved further than
/// the smallest radius in the world is traced from where it started the step to where it
/// ended, in index order; if it went through another sphere or a box, or its centre ended
/// behind a plane, it goes back to the moment of touching and its contacts are detected again
/// there, plus that touch unless the partner overlaps it there (see swept_spheres.cpp for why).
/// A sphere moved back keeps its start: later spheres are traced against the part of its path
/// it did travel. With the grid, only the candidates the broad phase found are tried, with the
/// same result as trying every body. `dt` and `gravity_term` give each body's start without a
/// grid (start_of_step()). scratch.moved lists the spheres moved back.
void sweep_fast_spheres(std::span<RigidBody> bodies, double dt, const Vector3& gravity_term, const SweepGrid& grid,
                        std::vector<Contact>& contacts, SweepScratch& scratch);

}  // namespace workbook
