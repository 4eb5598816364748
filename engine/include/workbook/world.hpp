#pragma once
/// \file
/// The world: bodies, a fixed time step and the explicit stages of one step.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "workbook/broad_phase.hpp"
#include "workbook/contact.hpp"
#include "workbook/event_timing.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/probes.hpp"
#include "workbook/response_model.hpp"
#include "workbook/rigid_body.hpp"
#include "workbook/sleeping.hpp"
#include "workbook/swept_spheres.hpp"

namespace workbook {

/// How integrate() advances velocities and positions over one step.
enum class Integrator : std::uint8_t {
    /// v += a dt, then x += v dt with the new v. Symplectic: energy errors stay bounded,
    /// which is why most game engines use it and why it is the default.
    semi_implicit_euler,
    /// x += v dt with the old v, then v += a dt. Gains energy steadily; kept to compare against.
    explicit_euler,
    /// x += v dt + 1/2 g dt^2, then v += g dt: the closed form of motion under constant gravity,
    /// so free flight has no truncation error at any time step (only rounding).
    exact_under_gravity,
};

/// When, within a step, contacts are answered.
enum class ContactTiming : std::uint8_t {
    /// Move every body the whole step, then answer whatever overlaps (the classic loop).
    discrete,
    /// Advance to the earliest time of impact of a sphere pair, or of a plane and a sphere or a
    /// box that does not spin (closed form under constant gravity), answer it there, and
    /// continue with the rest of the step.
    event,
};

/// Settings that do not change while a scene runs.
struct WorldSettings {
    double time_step = 1.0 / 240.0;  ///< s
    Vector3 gravity{};               ///< m/s^2; the zero vector turns gravity off
    Integrator integrator = Integrator::semi_implicit_euler;  ///< how integrate() advances the bodies
    PositionCorrection position_correction{};  ///< the knobs handed to the model's position corrector
    ContactTiming contact_timing = ContactTiming::discrete;  ///< when contacts are answered within a step
    /// Discrete timing only: a sphere that moves more than its radius in a step is swept along
    /// its path, so that a fast ball cannot pass through another body between two steps.
    bool swept_spheres = true;
    /// Stop with NonFiniteState (workbook/guards.hpp) when a stage leaves a NaN or an infinity
    /// in a body. On by default; benchmarks turn it off.
    bool check_finite = true;
    /// Iterations and warm starting of the contact solver, for models that have one.
    ContactSolverSettings contact_solver{};
};

/// Work a step leaves out when a scene does not need it. Each shortcut gives exactly the
/// result of doing the work (tests compare state hashes with it on and off, over every
/// chapter scene); only the speed differs. All are on by default; tests and benchmarks turn
/// them off to compare.
struct Shortcuts {
    /// Find candidate pairs with a grid (BroadPhase) instead of testing every pair ...
    bool broad_phase = true;
    /// ... from this many bodies on. Measured with bench/stages.cpp (detect_grid_or_all_pairs,
    /// the gas with four walls, CPU time, medians of 5): with 8 bodies testing every pair takes
    /// 428 ns and the grid 516 ns, with 16 the grid 748 ns against 1016 ns.
    std::size_t broad_phase_from = 12;
    /// Never pair two immovable bodies (no response could move them); off, such pairs are
    /// tested and their contacts dropped.
    bool skip_immovable_pairs = true;
    /// No rotation work for bodies that do not spin (angular velocity exactly zero, as for
    /// spheres under central impulses): no orientation update, no world inertia, no
    /// rotational terms in the probes, which are exactly zero for them.
    bool skip_still_rotation = true;
    /// No gravity kick when gravity is the zero vector (v + 0 dt is v).
    bool skip_zero_gravity = true;
    /// Measure the kinetic energy each response changes (the probe response_energy_change);
    /// a run that does not record it (a benchmark) turns this off and the probe reads 0.
    bool response_energy_probe = true;
};

/// Whether a stage or part of one runs for the world's scene, and why; the explain option
/// of the workbook's run command prints one line per stage.
struct StageUse {
    std::string_view stage;  ///< e.g. "broad phase"
    bool used = true;        ///< false when skipped
    std::string why;         ///< one line, with the numbers that decided it
};

/// Steps a set of rigid bodies with the chosen integrator and the scene's response model.
///
/// One step runs four stages in a fixed order, each callable on its own so that benchmarks
/// can time them and scenes can skip what they do not need:
///  1. integrate(): velocities from gravity, then positions and orientations from velocities
///     (a free body's rotation keeps its angular momentum, see rotation.hpp; a kinematic body,
///     immovable but given a velocity, moves at that velocity);
///  2. detect():    every overlapping pair, as a Contact;
///  3. respond():   the model's velocity responder, once per contact;
///  4. correct():   the model's position corrector, once per contact.
///
/// A model with a contact solver (chapter 5) replaces stages 3 and 4 by one,
/// solve_contacts(): every contact of the step solved together, velocities then overlap.
/// Under event timing, integrate_impact_to_impact() replaces stage 1 (the bodies move from
/// impact to impact, each answered at its moment), detect() looks only among the pairs that
/// came near, and keep_answered_impacts() ends the step. step() calls exactly these public
/// stages, so that bench/stages.cpp times what a step runs.
///
/// Storage is sized when the world is built; after the first step no stage allocates.
class World {
public:
    /// A world of `bodies` that steps with `settings` and answers contacts with `model`.
    World(std::vector<RigidBody> bodies, WorldSettings settings, ResponseModel model);

    /// Runs the four stages once, in order, and advances the clock: exactly integrate(),
    /// detect(), respond(), correct() (a test holds it to that, state hash for state hash).
    /// Under event timing, integrate_impact_to_impact() takes integrate()'s place: the bodies
    /// move from impact to impact within the step, each answered at its moment
    /// (event_timing.hpp); the same detect(), respond() and correct() then answer what still
    /// overlaps (detect() puts the impacts' contacts first, and respond() and correct() pass
    /// over them), and keep_answered_impacts() ends the step.
    void step();

    /// Stage 1: gravity, then positions and orientations. With the grid it also gathers the
    /// broad phase's proxies in the same pass, for the detect() that follows.
    void integrate();
    /// Stage 2: fills contacts() with every overlapping pair (and, with speculative contacts,
    /// every sphere and plane pair within ContactSolverSettings::speculative_distance, two
    /// spheres also within what they travelled: speculative_reach()), then (discrete timing, swept
    /// spheres on) traces each fast sphere along its path (swept_spheres.hpp). Right after
    /// integrate_impact_to_impact(), only the pairs whose bodies came near each other are tried.
    void detect();
    void respond();    ///< stage 3: the model's velocity responder, once per contact
    void correct();    ///< stage 4: the model's position corrector, once per contact
    /// Stage 1 under event timing: the bodies move from impact to impact within the step, each
    /// impact answered at its moment by the model's responder (move_impact_to_impact(),
    /// event_timing.hpp); the detect() that follows looks only among the pairs that came near.
    void integrate_impact_to_impact();
    /// Last under event timing: the impacts answered in integrate_impact_to_impact() are first in
    /// contacts() (detect() put them there, unless the bodies were changed since: then here),
    /// and the energy they changed joins response_energy_change.
    void keep_answered_impacts();
    /// Stages 3 and 4 for a model with a contact solver: all contacts of the step together.
    void solve_contacts();
    /// What the last solve_contacts() did (all zero for models without a contact solver).
    [[nodiscard]] const ContactSolverReport& contact_solver_report() const { return solver_report_; }
    /// The contact solver, with the impulses of its last solve.
    [[nodiscard]] const ContactSolver& contact_solver() const { return contact_solver_; }
    /// Which bodies sleep (a model with a contact solver, ContactSolverSettings::sleeping).
    [[nodiscard]] const Sleeping& sleeping() const { return sleeping_; }

    /// Simulated time since the start, s.
    [[nodiscard]] double time() const { return time_; }
    /// The fixed settings.
    [[nodiscard]] const WorldSettings& settings() const { return settings_; }
    /// The response model in use.
    [[nodiscard]] const ResponseModel& model() const { return model_; }
    /// The bodies, in scene order.
    [[nodiscard]] std::span<const RigidBody> bodies() const { return bodies_; }
    /// The bodies, writable (for tests and tools); the next detect() then gathers them afresh.
    [[nodiscard]] std::span<RigidBody> bodies() {
        proxies_fresh_ = false;
        impacts_fresh_ = false;
        at_rest_ = false;
        event_scratch_.copies_known = false;  // EventScratch::copies_known
        return bodies_;
    }
    /// True when the last step() found nothing to move (every movable body asleep, no
    /// kinematic body moving) where the step before had left it: it then detected and solved
    /// nothing, since both would have found what they found before.
    [[nodiscard]] bool at_rest() const { return skipped_; }
    /// The contacts found by the last detect(); under event timing, after the impacts the
    /// step answered at their moment.
    [[nodiscard]] std::span<const Contact> contacts() const { return contacts_; }

    /// The shortcuts in use.
    [[nodiscard]] const Shortcuts& shortcuts() const { return shortcuts_; }
    /// Turns shortcuts on or off, for tests and benchmarks; takes effect at the next stage.
    void set_shortcuts(const Shortcuts& shortcuts) { shortcuts_ = shortcuts; }
    /// True when the last detect() used the grid rather than testing every pair.
    [[nodiscard]] bool used_broad_phase() const { return used_broad_phase_; }

    /// Which stages this world's scene uses and which it skips, with the reason for each.
    [[nodiscard]] std::vector<StageUse> plan() const;

    /// Probes of the current state, including what the last respond() did to kinetic energy.
    [[nodiscard]] Probes probes() const;

    /// Names for the bodies, in scene order, used in error messages (may be left empty).
    void name_bodies(std::vector<std::string> names) { body_names_ = std::move(names); }
    /// The names given by name_bodies(), or an empty span.
    [[nodiscard]] std::span<const std::string> body_names() const { return body_names_; }
    /// Steps completed since the start.
    [[nodiscard]] std::uint64_t steps_taken() const { return steps_; }

private:
    /// Throws NonFiniteState naming `stage` when check_finite is on and a body is not finite.
    void guard(const char* stage) const;
    /// Appends the contact of bodies i < j when they overlap (never for two immovable ones).
    void add_contact_if_any(std::uint32_t i, std::uint32_t j);
    /// The same, from proxies_ (gathered this step) for spheres and planes.
    void add_contact_from_proxies(std::uint32_t i, std::uint32_t j);
    /// detect(); `gathered` when integrate_bodies() has filled proxies_ already (and, for a
    /// swept set, the broad phase also finds the swept test's candidates).
    void find_contacts(bool gathered);
    /// Stage 1; with `gather`, fills proxies_ in the same pass (and the swept test's starts
    /// when `swept`). Returns 0 when every body is finite afterwards, NaN otherwise.
    double integrate_bodies(bool gather, bool swept);
    /// How far apart a pair may be and still get a contact, m: the speculative distance of
    /// the contact solver (ContactSolverSettings::speculative_distance), 0 without one.
    [[nodiscard]] double contact_margin() const;
    /// True when detect() uses the grid for this world's size and shortcuts.
    [[nodiscard]] bool uses_grid() const;
    /// The guard for a stage that changed only the bodies `changed`.
    void guard_bodies(const char* stage, std::span<const std::uint32_t> changed) const;
    /// The contacts respond() and correct() answer: contacts_ without the impacts detect() put
    /// first under event timing (answered at their moment already).
    [[nodiscard]] std::span<const Contact> unanswered_contacts() const {
        return std::span<const Contact>(contacts_).subspan(answered_first_);
    }
    /// Stages 3 and 4; each returns 0 when the bodies it changed are finite, NaN otherwise.
    double respond_contacts();
    double correct_contacts();
    /// Fills proxies_ from the bodies as they stand, as integrate() would have (with the swept
    /// test's starts and travels when it runs).
    void gather_proxies();
    /// True when detect() runs the swept test (discrete timing, WorldSettings::swept_spheres).
    [[nodiscard]] bool sweeps_spheres() const;
    /// What start_of_step() (swept_spheres.hpp) takes back of gravity's move over a step,
    /// g c dt^2, for this world's integrator.
    [[nodiscard]] Vector3 start_gravity_term() const;
    /// How far `body` moved in the step, m, as gather_body() gives it to its proxy; 0 when the
    /// swept test is off (then no proxy has a travel either).
    [[nodiscard]] double travel_in_step(const RigidBody& body) const;
    /// Appends body i to proxies_, with its start and travel when `swept` (see integrate_bodies()).
    void gather_body(std::uint32_t i, bool swept, double dt, const Vector3& gravity_term, double& smallest_radius);

    std::vector<RigidBody> bodies_;
    std::vector<Contact> contacts_;
    BroadPhase broad_phase_;
    std::vector<BodyPair> pairs_;
    ProxySet proxies_;
    /// True from an integrate() that gathered proxies_ to the detect() that uses them.
    bool proxies_fresh_ = false;
    /// Whether the last integrate_bodies() moved anything: an awake body, or a kinematic one
    /// with a velocity or spin.
    bool moved_ = true;
    /// Set by a step in which nothing moved (every movable body asleep): its detection and
    /// solve were done at the positions the bodies still hold, so until something moves or
    /// bodies() hands them out, a step would find the same contacts and solve none of them,
    /// and step() skips both. Asleep islands then cost nothing.
    bool at_rest_ = false;
    bool skipped_ = false;  ///< the last step() skipped detection and solve (at_rest())
    SweepScratch sweep_scratch_;
    EventScratch event_scratch_;
    /// What the last integrate_impact_to_impact() left for the rest of the step.
    ImpactsAnswered impacts_;
    /// True from an integrate_impact_to_impact() that followed impacts to the detect() after it.
    bool impacts_fresh_ = false;
    /// True from a detect() that put the last integrate_impact_to_impact()'s contacts first in
    /// contacts_ to the keep_answered_impacts() after it, which then has nothing to move.
    bool impacts_placed_ = false;
    /// How many contacts at the front of contacts_ are impacts answered already (that detect()
    /// put there), for respond() and correct() to pass over; 0 otherwise.
    std::size_t answered_first_ = 0;
    Shortcuts shortcuts_;
    bool used_broad_phase_ = false;
    WorldSettings settings_;
    ResponseModel model_;
    double time_ = 0.0;
    double response_energy_change_ = 0.0;
    std::vector<std::string> body_names_;
    std::uint64_t steps_ = 0;
    ContactSolver contact_solver_;
    ContactSolverReport solver_report_;
    Sleeping sleeping_;
    /// The contacts the solver gets while some bodies sleep: those with an awake movable body.
    std::vector<Contact> awake_contacts_;
    /// The others: a sleeping island's contacts, whose impulses the solver keeps for its waking.
    std::vector<Contact> asleep_contacts_;
};

}  // namespace workbook
