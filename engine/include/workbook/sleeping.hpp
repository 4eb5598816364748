#pragma once
/// \file
/// Sleeping (chapter 5's contact solver only): a group of bodies that has stood still for a
/// while stops costing anything until something touches it.
///
/// Bodies that touch each other, directly or through others, form an island (immovable bodies
/// such as the ground join none: a pile on the ground is one island, two stacks on it are
/// two). When every body of an island has moved slower than `sleep_speed` for `sleep_time`,
/// the island falls asleep: its velocities become exactly zero, and integration and the
/// contact solver skip its bodies and their contacts. Detection still runs over them, so
/// that a moving body that touches one of them wakes its whole island in the same step;
/// once every body sleeps and nothing else moves, World::step() skips detection too
/// (World::at_rest()).
/// What sleeping changes: a sleeping body stands exactly still instead of creeping by
/// rounding (or jittering, in a pile whose passes did not converge); its kinetic energy is 0.

#include <cstdint>
#include <span>
#include <vector>

#include "workbook/contact.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

/// Which bodies sleep, the islands of a step and how long each body has been still.
/// Sized once for the world's bodies: a warm step allocates nothing.
class Sleeping {
public:
    /// True when body `i` sleeps.
    [[nodiscard]] bool asleep(std::size_t i) const { return sleeping_ > 0 && asleep_[i] != 0; }
    /// How many bodies sleep.
    [[nodiscard]] std::size_t sleeping() const { return sleeping_; }

    /// After detection: finds this step's islands and wakes every sleeping island that an
    /// awake body (or a moving kinematic body) touches.
    void wake_touched(std::span<RigidBody> bodies, std::span<const Contact> contacts);

    /// After the solve: counts how long each awake body has been still and puts to sleep every
    /// island all of whose bodies have been still for `settings.sleep_time`.
    void fall_asleep(std::span<RigidBody> bodies, const ContactSolverSettings& settings, double dt);

    /// The bodies the last wake_touched() woke (one flag per body), or an empty span when it
    /// woke none: they slept through this step's move, so it gave them no gravity.
    [[nodiscard]] std::span<const std::uint8_t> woken() const {
        return woken_count_ > 0 ? std::span<const std::uint8_t>(woken_) : std::span<const std::uint8_t>{};
    }

    /// Wakes body `i` (its island wakes at the next wake_touched()).
    void wake(std::size_t i);

    /// Wakes every body.
    void wake_all();

private:
    std::uint32_t root(std::uint32_t i);
    void size_for(std::size_t count);

    std::vector<std::uint32_t> parent_;     ///< union-find over movable bodies; a root is its own parent
    std::vector<double> still_;             ///< s each body has been slower than sleep_speed
    std::vector<std::uint8_t> asleep_;      ///< 1 for a sleeping body
    std::vector<std::uint8_t> island_awake_;  ///< per root: some body of the island is awake
    std::vector<double> island_still_;      ///< per root: the shortest still time of its bodies
    std::size_t sleeping_ = 0;
    std::vector<std::uint8_t> woken_;       ///< 1 for a body the last wake_touched() woke
    std::size_t woken_count_ = 0;
};

}  // namespace workbook
