#pragma once
/// \file
/// What a scene file may ask for. A scene beyond these would need absurd work or memory, or
/// would overflow double arithmetic on the way (1/2 m v^2, m g . x), so the loader refuses it
/// before anything runs, naming the field and the limit.

#include <cstddef>

namespace workbook {

/// The limits every scene is checked against, with the reason for each.
struct SceneLimits {
    /// duration / time_step. run() keeps one ~110-byte probe sample per step: 10^7 steps is
    /// about a gigabyte.
    double max_steps = 1e7;
    /// The world stores contacts in proportion to the contacts there are and finds pairs with a
    /// uniform grid (broad_phase.hpp), about 500 bytes a body: 10^5 bodies is the largest the speed
    /// bench runs (it builds its worlds in code); scene files stop at 10^4, which the sanitizer
    /// build still parses in seconds.
    std::size_t max_bodies = 10000;
    /// s. No contact scene needs a coarser step, and with every other limit below, v dt and
    /// g dt^2 then stay far from overflow (a step of 1e200 s overflowed at the first step).
    double max_time_step = 1.0;
    /// m/s, per velocity component. 10^8 m/s squared times the largest mass stays far below
    /// the largest double (~1.8e308), as does every impulse and energy built from it.
    double max_speed = 1e8;
    /// m, per position component.
    double max_coordinate = 1e12;
    /// rad/s, per angular velocity component.
    double max_angular_speed = 1e8;
    /// kg. With the speed and position limits this keeps every product the engine forms finite,
    /// and leaves room for mass ratios of 10^24.
    double min_mass = 1e-12;
    double max_mass = 1e12;  ///< kg
    double min_radius = 1e-9;  ///< m
    double max_radius = 1e9;   ///< m
    /// m, each of a box's half extents: the same range as a radius. A box of 1e-160 m (or
    /// 1e200 m) has an inertia m h^2 that underflows to zero (or overflows), and gave a NaN
    /// at its first contact.
    double min_half_extent = 1e-9;
    double max_half_extent = 1e9;  ///< m
    /// rad per time step: how far a free body with unequal moments may turn in one step,
    /// measured as largest_spin() dt (workbook/rotation.hpp). The rotation step follows up
    /// to max_turn_per_substep * max_substeps (1024 rad) with energy constant to rounding;
    /// a faster spin is refused, naming the body, rather than run with energy drifting.
    double max_turn_per_step = 1024.0;
    /// m/s^2, per gravity component (100 g is about 981 m/s^2).
    double max_gravity = 1e6;
    /// Largest coefficient of friction (static or dynamic). Real pairs lie below about 2
    /// (silicone rubber); 10 leaves room for experiments, and mu J_n stays finite.
    double max_friction = 10.0;
};

/// The limits the scene loader applies.
inline constexpr SceneLimits scene_limits{};

}  // namespace workbook
