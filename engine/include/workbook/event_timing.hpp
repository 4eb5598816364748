#pragma once
/// \file
/// Event-accurate contact timing: within a step, advance to the earliest time of impact,
/// answer that contact there, and continue with the rest of the step.
///
/// Between impacts every movable body follows the motion its integrator gives over a
/// sub-interval tau, x(tau) = x + v tau + k g tau^2 with k = 1/2 for exact-under-gravity, 1 for
/// semi-implicit Euler and 0 for explicit Euler. A sphere's height over a plane, and the squared
/// distance between two spheres that share the same acceleration, are then quadratics in tau,
/// so the time of impact has a closed form. So is the height over a plane of a box that does
/// not spin: its lowest corner moves with its centre. The one case without a closed form, a
/// movable sphere falling onto an immovable sphere, is a quartic and is bracketed and bisected
/// instead. Spinning boxes, and boxes against spheres or boxes, are left to the discrete
/// back-stop.

#include <optional>

#include "workbook/rigid_body.hpp"
#include "workbook/world.hpp"

namespace workbook {

/// k in x(tau) = x + v tau + k g tau^2 for `integrator` (see the file comment).
double gravity_position_factor(Integrator integrator);

/// The earliest tau in [0, limit] at which `a` and `b` (sphere-sphere, sphere-plane, or a box
/// that does not spin and a plane, in either order) come into contact while approaching, or
/// nothing. Pairs that already overlap by more than rounding are left to the discrete back-stop.
std::optional<double> time_of_impact(const RigidBody& a, const RigidBody& b, const Vector3& gravity, double k,
                                     double limit);

/// One step of `world` with event-accurate timing. After the last event the discrete stages
/// run once on what still overlaps (deep initial overlaps, resting contacts), so nothing is
/// left unanswered. A step handles at most a bounded number of events, after which the rest
/// of it is discrete: a ball coming to rest on the ground bounces infinitely often in a
/// finite time, and no event loop can follow that.
void step_with_event_timing(World& world);

}  // namespace workbook
