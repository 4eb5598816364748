#pragma once
/// \file
/// Solving every contact of a step together (chapter 5, resting contact): the data the solver
/// keeps per contact point, its settings, and the hooks through which the world calls the
/// chapter's functions.
///
/// One pass of impulses, one contact after another, is exact for a single contact and wrong
/// for a stack: pushing the top box up off the second pushes the second down into the third.
/// The solver here goes over all contacts again and again (sequential impulses), keeping per
/// point the impulse accumulated so far within the step and only that sum non-negative, so
/// that a later pass can take back what an earlier one gave too much. Overlap is removed in a
/// second, separate pass on pseudo-velocities (split impulse): they move the bodies and are
/// then thrown away, so removing overlap never adds kinetic energy.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "workbook/contact.hpp"
#include "workbook/response_model.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

/// What the solver keeps of one point of one contact, within a step and (the two impulses)
/// from one step to the next.
struct PointImpulse {
    double mass = 0.0;     ///< 1 / k, kg: the impulse that changes the point's normal velocity by 1 m/s (0: nothing moves)
    double bounce = 0.0;   ///< normal relative velocity the velocity pass aims for, m/s (restitution; 0 at rest)
    double bias = 0.0;     ///< normal pseudo-velocity the position pass aims for, m/s: the overlap to remove / dt
    double normal = 0.0;   ///< impulse accumulated along +n on body 1 this step, kg m/s; kept >= 0
    double pseudo = 0.0;   ///< pseudo-impulse accumulated by the position pass this step, kg m/s; kept >= 0
    /// Friction impulse accumulated along the two tangents of friction_tangents(), kg m/s
    /// (chapter 6); its length kept within the friction cone of `normal`. Warm started from
    /// the last step like `normal`; always 0 for a model without a friction pass.
    std::array<double, 2> friction{};
};

/// Two unit vectors that with `normal` make a right-handed orthonormal frame (n, t1, t2):
/// the directions friction acts along. The same normal always gives the same pair. The
/// engine's copy of chapter 6's step 2 (friction::tangent_basis()), for chapter 5's warm
/// start.
std::array<Vector3, 2> friction_tangents(const Vector3& normal);

/// The solver's numbers for every point of one contact (the first `point_count` of the contact).
struct ContactImpulses {
    std::array<PointImpulse, max_contact_points> points{};  ///< one per contact point, in the contact's order
};

/// How the contact solver works; the defaults are the ones measured on the pile of discs.
struct ContactSolverSettings {
    int velocity_iterations = 100;  ///< most passes over all contacts for the velocities
    int position_iterations = 100;  ///< most passes over all contacts for the overlap
    /// A pass that changes no point's normal velocity by more than this (m/s) ends the loop
    /// early: nothing approaches any more (to this tolerance).
    double tolerance = 1e-9;
    /// Start each step from the impulses the same points needed in the last step.
    bool warm_start = true;
    /// A point that approaches slower than this (m/s) gets no bounce: resting bodies would
    /// otherwise bounce on gravity's own speed of one step (g dt = 0.16 m/s at 60 Hz).
    double bounce_threshold = 0.5;
    /// Old and new points of the same pair with a box are the same point (for warm starting)
    /// when they lie closer than this, m. A pair of spheres and planes has one point, matched
    /// by the pair alone.
    double match_distance = 0.01;
    /// Most overlap a point's bias asks to remove in one step, m: a deep overlap pushed out at
    /// once would push bodies through their neighbours.
    double max_push = 0.005;
    /// 0: the scheme above, one solve per step (rigid passes to the tolerance, then the
    /// overlap on pseudo-velocities). n > 0: the step is solved in n substeps of dt / n
    /// (soft step): in each, gravity's share, the warm start, one pass on soft contacts that
    /// push the overlap out, the move, and `relax_passes` rigid passes (relax) that take that
    /// push back out of the velocities; the bounce comes in a last pass. The iteration
    /// counts, the tolerance and PositionCorrection::fraction are then not used (the slop is),
    /// and the impulses the solver keeps (ContactSolver::impulses()) are each substep's.
    int substeps = 0;
    /// With substeps: the rigid passes (relax) after each substep's move. One pass, Box2D's,
    /// takes the push back out exactly at a lone contact but not in a deep pile, where one
    /// pass over the contacts leaves part of every point's push in the velocities: kinetic
    /// energy that the next push adds to. In a block of discs started touching, at 12
    /// substeps of 180 Hz without speculative contacts, that leftover grows until the block
    /// collapses into itself; a second pass takes enough of it back, and so do speculative
    /// contacts with one (tests/engine/contact_solver.cpp). Each pass adds about a quarter to
    /// the time of a step of the bench's pile of discs.
    int relax_passes = 2;
    /// With substeps: the stiffness of a soft contact, Hz (at most a quarter of the substep
    /// rate, the highest a substep resolves). A contact then acts as a spring of that
    /// frequency for the point's effective mass.
    double contact_hertz = 30.0;
    /// With substeps: the damping ratio of a soft contact's spring (far above 1: it pushes
    /// the overlap out without swinging back).
    double contact_damping_ratio = 10.0;
    /// Shock propagation (Guendelman, Bridson and Fedkiw 2003, "Nonconvex rigid bodies with
    /// stacking"); without substeps only. 0: off. n > 0: after the velocity passes, n sweeps
    /// over the contacts from the bottom up (the passes' order) in which, at a contact whose
    /// normal leans out of the horizontal by more than `shock_slope`, the lower body counts
    /// as immovable: only the upper one is pushed, so that after the sweep no body comes down
    /// onto the bodies it rests on. A jammed row then cannot be squeezed sideways by the rows
    /// wedged in above it, which the passes, carrying a change along a row by one contact a
    /// pass, take about the square of the row's length in passes to settle. A contact whose
    /// one-sided solve would give the upper body kinetic energy (its lower neighbour moving
    /// into it faster than it comes down) is solved two-sided instead: a sweep never adds
    /// kinetic energy. A contact with one movable body (on the ground, or on its frozen
    /// lower body) is solved to `tolerance`, not in one call: a face's points share the
    /// body's spin. Where friction acts the sweep answers friction after the normal, as the
    /// passes do, except at a point that bounces (friction's phase came before its bounce).
    /// A contact between bodies side by side stays two-sided. Without gravity
    /// there is no up, and a sweep is one more pass. Measured on the pile of discs
    /// (docs/performance.md): alone it settles a packed block of discs that the passes leave
    /// moving, but not the pile dropped into its box, whose landing puts discs deep into
    /// each other before any contact exists; with speculative contacts (below) one sweep
    /// holds the pile's overlap within 5 mm from 400 to 20,000 discs. With friction it holds a
    /// stack of thirty boxes up that the passes alone let fall over.
    int shock_sweeps = 1;
    /// With shock_sweeps: the sine of the smallest lean of a contact's normal out of the
    /// horizontal for its lower body to count as immovable.
    double shock_slope = 0.1;
    /// Islands of bodies that stand still fall asleep and cost nothing until touched
    /// (workbook/sleeping.hpp).
    bool sleeping = true;
    /// A body is still while its centre, and any point of it through its spin, moves slower
    /// than this, m/s.
    double sleep_speed = 0.01;
    /// An island falls asleep when every body of it has been still this long, s.
    double sleep_time = 0.5;
    /// Speculative contacts, m (0: off). Detection also reports pairs
    /// that are apart by less than this (a point of negative depth: the gap; for a pair with
    /// a box, the points it would touch at first, box_detection.hpp),
    /// and the solver lets such a point approach only as fast as closes its gap within the
    /// step: a body pushed by the solve towards a neighbour it does not touch yet stops
    /// touching it instead of passing into it unseen (the deep overlaps of a pile that falls
    /// onto itself, docs/performance.md). A gap gets no bias, and a bounce only when the pair
    /// would meet in the next move fast enough to bounce (it then bounces a gap short of
    /// touching); the chapter's functions see its depth as 0.
    ///
    /// How far apart a pair may be and still matter: the solve changes a body's velocity by
    /// at most about the speed of what hits it, and moves it by that change times dt; in a
    /// pile the change passed down from a landing disc is a few m/s, a few centimetres a
    /// step at 60 Hz. A larger distance catches more and costs more pairs (in a packed pile
    /// of discs, up to a quarter of a diameter adds only the six nearest neighbours). 2 cm is
    /// the gap between the rows the bench's pile starts in, and did as well there as 5 cm.
    /// Two bodies that are not planes also reach as far as both travelled in the step
    /// (speculative_reach(), with the swept test on): the solve may stop a body that still
    /// moves at its own speed while the body behind it keeps going, as at the top of a column
    /// that is landing, which closes their gap by that speed times the step, whatever the
    /// distance.
    double speculative_distance = 0.02;
};

/// The chapter's functions the solver calls (see chapters/resting-contact). Each works on one
/// contact of two bodies, so that the student's copy can be called across the grader's wire.
struct ContactSolverHooks {
    /// Fills mass, bounce and bias of every point (the impulses are left as the world set them).
    void (*prepare)(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
                    const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt) = nullptr;
    /// Applies the accumulated normal impulses (the last step's, for warm starting); not called
    /// for a model with a friction pass and `tangents` (the solver warm starts those itself).
    void (*warm_start)(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) = nullptr;
    /// One pass over the contact's points for the velocities; returns the largest change of a
    /// point's normal velocity, m/s.
    double (*solve_velocity)(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) = nullptr;
    /// One pass over the contact's points for Coulomb friction (chapter 6), called after
    /// solve_velocity on the same contact, with the coefficients of the bodies
    /// (RigidBody::friction, RigidBody::static_friction); returns the largest change of a
    /// point's slip, m/s. Null for a model without friction: a scene whose bodies have friction
    /// is then refused (workbook::make_world()).
    double (*solve_friction)(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) = nullptr;
    /// One pass over the contact's points for the overlap, on bodies whose velocities are the
    /// pseudo-velocities; returns the largest change of a point's normal pseudo-velocity, m/s.
    double (*solve_position)(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) = nullptr;
    /// The two tangents solve_friction accumulates `PointImpulse::friction` along (chapter 6's
    /// friction::tangent_basis()). With a friction pass the solver warm starts each point
    /// itself, normal and friction impulses along these very tangents, instead of calling
    /// warm_start: the remembered friction is then applied along the directions it was
    /// accumulated in, whatever warm_start does with it.
    std::array<Vector3, 2> (*tangents)(const Vector3& normal) = nullptr;
};

/// What one solve did, for probes, figures and the iterations-against-accuracy study.
struct ContactSolverReport {
    int velocity_passes = 0;  ///< passes the velocity loops ran (both phases with friction)
    int position_passes = 0;  ///< passes the position loop ran
    double velocity_residual = 0.0;  ///< the last velocity pass's largest change, m/s
    double position_residual = 0.0;  ///< the last position pass's largest change, m/s
    std::size_t warm_started_points = 0;  ///< points that found their last step's impulse
};

/// The solver: holds what it remembers between steps (the impulses of last step's contact
/// points) and its scratch, sized once and reused, so a warm step allocates nothing.
class ContactSolver {
public:
    /// Solves every contact of `contacts` on `bodies` with the chapter's `hooks`, `up` pointing
    /// against gravity (any direction without gravity):
    ///  1. prepare each contact (masses, bounce and bias), warm start from the last step;
    ///  2. up to velocity_iterations passes over all contacts, until nothing approaches;
    ///     with a friction pass (chapter 6) first without bounce, friction included, then
    ///     up to as many passes again along the normals alone for the bounce (Newton's
    ///     restitution solved together with friction can create energy); the change of
    ///     velocity also moves each body over this step (as if the solve had come before the
    ///     move), and each point's depth is estimated after that move; with
    ///     settings.shock_sweeps, the sweeps of shock propagation follow the passes (their
    ///     change of the velocities moves the bodies too);
    ///  3. up to position_iterations passes on pseudo-velocities that start at zero;
    ///     each body then moves by its pseudo-velocity times dt, and they are forgotten.
    ///
    /// With settings.substeps > 0 the step is solved in substeps instead (see
    /// ContactSolverSettings::substeps), which needs how the world moved the bodies before the
    /// solve: `gravity`, added to every velocity over dt, and `gravity_position_factor`, the
    /// share of gravity's kick that was in the move (1 for semi-implicit Euler). The bodies of
    /// the contacts then move as if gravity had come in dt / n at a time. `woken` (empty, or
    /// one flag per body) marks the bodies that slept through that move and woke after it:
    /// they got neither gravity nor a move, so the substeps start them where they stand.
    ContactSolverReport solve(std::span<RigidBody> bodies, std::span<const Contact> contacts, const ContactSolverHooks& hooks,
                              const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt,
                              const Vector3& up, const Vector3& gravity = {}, double gravity_position_factor = 1.0,
                              std::span<const std::uint8_t> woken = {});

    /// Keeps, for warm starting, the impulses last remembered for the pairs of `contacts`:
    /// the contacts of sleeping islands, which the world leaves out of solve(). An island
    /// then wakes with the impulses that held it when it fell asleep, instead of cold (a
    /// woken pile that starts from zero impulses sinks into itself for a few steps).
    /// Call it after solve(), with that step's sleeping contacts.
    void keep_for_waking(std::span<const Contact> contacts);

    /// The impulses of the last solve, one per contact, in the contacts' order.
    [[nodiscard]] std::span<const ContactImpulses> impulses() const { return impulses_; }

    /// Makes room for `contacts` contacts in what the solver keeps and its scratch (the world
    /// calls it with its contact list's capacity, so that the solver allocates only in the
    /// steps where that list grows).
    void reserve(std::size_t contacts);

    /// Forgets the impulses remembered for warm starting.
    void forget() { previous_.clear(); }

private:
    // One remembered contact: its pair, normal, points and their impulses. Kept out of the
    // site: a private type the API reference has no page for.
    /// \cond
    struct Remembered {
        std::uint64_t pair = 0;
        Vector3 normal{};
        std::array<Vector3, max_contact_points> positions{};
        std::array<double, max_contact_points> normal_impulses{};
        std::array<std::array<double, 2>, max_contact_points> friction_impulses{};
        std::uint8_t point_count = 0;
    };
    /// What a substep needs of one contact point: the chapter's mass and bounce (restored
    /// after the substeps change them), the depth found by detection and the lever arms.
    struct SoftPoint {
        double mass = 0.0;
        double bounce = 0.0;
        double depth = 0.0;
        Vector3 r1{};
        Vector3 r2{};
    };
    /// \endcond
    /// `detected`: the contacts as detection found them; `contacts`: the same as the chapter's
    /// functions see them (speculative depths at 0).
    void solve_in_substeps(std::span<RigidBody> bodies, std::span<const Contact> detected, std::span<const Contact> contacts,
                           const ContactSolverHooks& hooks,
                           const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt,
                           const Vector3& gravity, double gravity_position_factor, std::span<const std::uint8_t> woken,
                           ContactSolverReport& report);
    /// Puts into `impulses_of` (one per contact, in the order of `contacts`) the impulses last
    /// remembered for the same points: the one point of a pair of smooth bodies (spheres and
    /// planes) by the pair, the points of a pair with a box by where they lie (match_distance).
    void recall(std::span<const RigidBody> bodies, std::span<const Contact> contacts, std::span<ContactImpulses> impulses_of,
                const ContactSolverSettings& settings, ContactSolverReport& report);
    /// Sets order_: the contacts from the bottom up along `up`.
    void order_passes(std::span<const Contact> contacts, const Vector3& up);
    /// Copies `contacts` in the order of the passes into staged_, as the chapter's functions
    /// see them (with speculative contacts, every depth at least 0), with rank_ and zero
    /// impulses in staged_impulses_ beside them.
    void stage(std::span<const Contact> contacts, bool speculative);
    /// Copies the bodies of the staged contacts into staged_bodies_, in the order the passes
    /// first meet them, and sets global_ and pairs_; returns staged_bodies_.
    std::span<RigidBody> gather(std::span<const RigidBody> bodies);
    /// The rigid solve (steps 1 to 3 of solve()) on the staged contacts and impulses and the
    /// gathered `bodies`; `contacts` are the contacts as detected, in detection's order.
    void solve_staged(std::span<RigidBody> bodies, std::span<const Contact> contacts, const ContactSolverHooks& hooks,
                      const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt, const Vector3& up,
                      ContactSolverReport& report);
    /// Writes the gathered bodies back into `bodies` and the staged impulses into impulses_,
    /// in detection's order.
    void put_back(std::span<RigidBody> bodies);
    void remember(std::span<const Contact> contacts);

    std::vector<ContactImpulses> impulses_;
    std::vector<Contact> adjusted_;  ///< the contacts, in the order of the passes, with each point's depth after the velocity solve's move
    std::vector<std::uint32_t> order_;  ///< the contacts in the order of the passes
    std::vector<std::uint32_t> rank_;   ///< each contact's place in that order
    std::vector<Contact> staged_;       ///< the contacts in that order, as the chapter's functions see them
    std::vector<ContactImpulses> staged_impulses_;  ///< their impulses, in that order
    std::vector<std::array<std::uint32_t, 2>> pairs_;  ///< the staged contacts' two bodies among staged_bodies_
    std::vector<RigidBody> staged_bodies_;  ///< copies of the bodies of the staged contacts, in the order the passes first meet them
    std::vector<std::uint32_t> global_;     ///< each staged body's index in the world
    std::vector<std::uint32_t> local_;      ///< each body's index among staged_bodies_ (or none)
    std::vector<double> height_;        ///< each contact's height along `up`, for the order
    std::vector<Remembered> previous_;
    std::vector<Remembered> current_;
    std::vector<std::array<std::uint64_t, 2>> sort_keys_;  ///< (pair, contact) for remember()'s sort
    std::vector<double> bounces_;  ///< each point's bounce, put aside while friction's phase runs
    std::vector<std::uint8_t> gap_target_;  ///< 1 for a speculative point whose target only keeps its gap (no bounce)
    std::vector<Vector3> saved_velocity_;
    std::vector<Vector3> saved_angular_velocity_;
    std::vector<SoftPoint> soft_points_;  ///< max_contact_points per contact, in the contacts' order
    std::vector<Vector3> shift_;          ///< each body's move since detection, within the substeps
    std::vector<Vector3> turn_;           ///< each body's turn since detection, within the substeps
    std::vector<std::uint8_t> touched_;   ///< 1 for a movable body of some contact
    /// With speculative contacts: the contacts as the chapter's functions see them (every
    /// depth at least 0), in the contacts' order.
    std::vector<Contact> seen_;
};

}  // namespace workbook
