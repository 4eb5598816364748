#pragma once
/// \file
/// The world: bodies, a fixed time step and the explicit stages of one step.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "workbook/contact.hpp"
#include "workbook/probes.hpp"
#include "workbook/response_model.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

/// How integrate() advances velocities and positions over one step.
enum class Integrator : std::uint8_t {
    /// v += a dt, then x += v dt with the new v. Symplectic: energy errors stay bounded,
    /// which is why most game engines use it and why it is the default.
    semi_implicit_euler,
    /// x += v dt with the old v, then v += a dt. Gains energy steadily; kept to compare against.
    explicit_euler,
};

/// Settings that do not change while a scene runs.
struct WorldSettings {
    double time_step = 1.0 / 240.0;  ///< s
    Vector3 gravity{};               ///< m/s^2; the zero vector turns gravity off
    Integrator integrator = Integrator::semi_implicit_euler;  ///< how integrate() advances the bodies
};

/// Steps a set of rigid bodies with the chosen integrator and the scene's response model.
///
/// One step runs four stages in a fixed order, each callable on its own so that benchmarks
/// can time them and scenes can skip what they do not need:
///  1. integrate(): velocities from gravity, then positions and orientations from velocities;
///  2. detect():    every overlapping pair, as a Contact;
///  3. respond():   the model's velocity responder, once per contact;
///  4. correct():   the model's position corrector, once per contact.
///
/// Storage is sized when the world is built; after the first step no stage allocates.
class World {
public:
    /// A world of `bodies` that steps with `settings` and answers contacts with `model`.
    World(std::vector<RigidBody> bodies, WorldSettings settings, ResponseModel model);

    /// Runs the four stages once and advances the clock.
    void step();

    void integrate();  ///< stage 1: gravity, then positions and orientations
    void detect();     ///< stage 2: fills contacts() with every overlapping pair
    void respond();    ///< stage 3: the model's velocity responder, once per contact
    void correct();    ///< stage 4: the model's position corrector, once per contact

    /// Simulated time since the start, s.
    [[nodiscard]] double time() const { return time_; }
    /// The fixed settings.
    [[nodiscard]] const WorldSettings& settings() const { return settings_; }
    /// The response model in use.
    [[nodiscard]] const ResponseModel& model() const { return model_; }
    /// The bodies, in scene order.
    [[nodiscard]] std::span<const RigidBody> bodies() const { return bodies_; }
    /// The bodies, writable (for tests and tools).
    [[nodiscard]] std::span<RigidBody> bodies() { return bodies_; }
    /// The contacts found by the last detect().
    [[nodiscard]] std::span<const Contact> contacts() const { return contacts_; }

    /// Probes of the current state, including what the last respond() did to kinetic energy.
    [[nodiscard]] Probes probes() const;

private:
    std::vector<RigidBody> bodies_;
    std::vector<Contact> contacts_;
    WorldSettings settings_;
    ResponseModel model_;
    double time_ = 0.0;
    double response_energy_change_ = 0.0;
};

}  // namespace workbook
