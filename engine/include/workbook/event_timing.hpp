#pragma once
/// \file
/// Event-accurate contact timing: within a step, advance to the earliest time of impact,
/// answer that contact there, and continue with the rest of the step.
///
/// Between impacts every movable body follows the motion its integrator gives over a
/// sub-interval tau, x(tau) = x + v tau + k g tau^2 with k = 1/2 for exact-under-gravity, 1 for
/// semi-implicit Euler and 0 for explicit Euler; a kinematic body moves at its set velocity.
/// A sphere's height over a plane, and the squared distance between two spheres that share
/// the same acceleration, are then quadratics in tau, so the time of impact has a closed form.
/// So is the height over a plane of a box that does not spin: its lowest corner moves with its
/// centre. The one case without a closed form, a movable sphere falling onto an immovable
/// sphere, is a quartic and is bracketed and bisected instead; a sphere against a box that does
/// not spin is sampled along its path and bisected too. Spinning boxes, two boxes, and planes
/// that turn are left to the discrete back-stop.
///
/// Why it scales: the pairs that may meet within a step are found once per step by the broad
/// phase, each body's bounding sphere widened by how far it may move in the step; each body
/// keeps the time its state refers to and is advanced only when it takes part in an event (and
/// at the end of the step), and the events wait in a queue by time. An event then costs the
/// times of impact of its two bodies with their candidates, not of every pair in the world. Those
/// predictions read compact copies of what they need of each body (EventBody, EventRole), not
/// the bodies, which are read and written only where an event changes them.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "workbook/broad_phase.hpp"
#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

enum class Integrator : std::uint8_t;
struct ResponseModel;

/// k in x(tau) = x + v tau + k g tau^2 for `integrator` (see the file comment).
double gravity_position_factor(Integrator integrator);

/// The earliest tau in [0, limit] at which `a` and `b` (sphere-sphere, sphere-plane, or a box
/// that does not spin and a plane or a sphere, in either order) come into contact while approaching, or
/// nothing. Pairs that already overlap by more than rounding are left to the discrete back-stop.
std::optional<double> time_of_impact(const RigidBody& a, const RigidBody& b, const Vector3& gravity, double k,
                                     double limit);

/// A predicted impact of bodies i < j at time t within the step; stale once either body has
/// taken part in a later event (its count of events no longer matches).
struct ImpactEvent {
    double t;                          ///< when, s from the start of the step
    std::uint32_t i;                   ///< the first body (the smaller index)
    std::uint32_t j;                   ///< the second body
    std::uint32_t events_i;            ///< body i's event count when it was predicted
    std::uint32_t events_j;            ///< body j's event count when it was predicted
};

/// Where a sphere ends a step under event timing (radius -1 for a body that is not a sphere).
struct SphereEnd {
    Vector3 centre;   ///< m
    double radius;    ///< m
};

/// What the event loop reads of a body at every prediction, kept next to each other: 64 bytes
/// (one cache line) where a RigidBody is 328. A pile predicts about a dozen pairs per body and
/// step, most of them between two spheres, and reading two whole bodies for each cost more
/// than the time of impact itself (at N = 100,000 the bodies fit in no cache). A copy of the
/// body's own numbers, refreshed whenever the loop changes the body, so that predictions give
/// bit for bit what they gave when they read the body.
struct EventBody {
    Vector3 position;        ///< m, at time `since`
    Vector3 velocity;        ///< m/s, at time `since`
    double since = 0.0;      ///< the time within the step the state refers to, s
    double bounding_radius = 0.0;  ///< m (workbook::bounding_radius; unused for a plane)
};

/// What kind of body the event loop has, a byte per question, for the tests it makes before it
/// reads any numbers.
struct EventRole {
    bool takes_part = false;  ///< followed by the event loop (a sphere, or a plane or box that does not spin)
    bool immovable = false;   ///< immovable or kinematic: gravity and impacts do not move it
    bool sphere = false;      ///< a sphere: its impacts with spheres are timed from its EventBody alone
    bool plane = false;       ///< a plane: unbounded, no bounding sphere
};

/// Where a body started the step and how far from there it may get within it, as its
/// candidates were last searched for; read together at each event of the body (outran()), so
/// kept together: at N = 100,000 the test read the body's proxy and its reach from two arrays,
/// two misses of the caches.
struct EventReach {
    Vector3 origin;       ///< the body's centre at the start of the step, m
    double reach = 0.0;   ///< how far from the origin it may get, m
    /// When the step uses boxes (EventScratch::use_boxes): half the sides of a box about the
    /// origin that holds the body over the step, m (its bounding radius and how far it may get
    /// along each axis). Two bodies whose boxes are apart cannot meet however near their
    /// widened spheres come: a ball that moves up and down has a box as narrow as itself
    /// across, and the neighbours beside it are no candidates. Here rather than in an array of
    /// its own, which the test whether a body outran its reach then read as well: one more
    /// miss of the caches per event, and the pile's step at N = 100,000 about 4% slower that
    /// way (near the noise). Left as it was in a step without boxes.
    Vector3 half_sides;
};

/// What move_impact_to_impact() keeps between steps, so that a warm step allocates nothing.
struct EventScratch {
    std::vector<EventBody> state;          ///< per body: what a prediction reads (EventBody)
    std::vector<EventRole> roles;          ///< per body: what kind of body it is for the loop
    /// Whether `state` and `roles` hold every body as the last step left it (its position and
    /// velocity at the start of the next step, its kind and bounding radius), but for the
    /// bodies of its overlapping pairs (all_pairs), which the discrete stages after it may have
    /// changed (the loop itself notes again every body it changes, after each response, so
    /// its copies end as the bodies are, even where a responder changed a mass). The next
    /// step's first pass then notes again only those, and reads the others' copies rather than
    /// the bodies: at N = 100,000 the bodies (328 bytes each) come from memory, and the first
    /// pass read them all. Set at the end of every step; the World
    /// clears it wherever the bodies may change otherwise (World::bodies(), its discrete
    /// stages called on their own), and a change in the number of bodies overrides it.
    bool copies_known = false;
    std::vector<Vector3> normals;          ///< per body: a plane's unit normal in the world (unset for other shapes)
    std::vector<EventReach> reach;         ///< per body: where it started the step, how far it may get
    /// Whether the next step uses boxes: they cost a pass over the bodies and one over the
    /// broad phase's pairs, and pay only where they leave out many pairs. A step with boxes
    /// that leaves out fewer than half of them turns them off for 15 steps (steps_without_boxes).
    bool use_boxes = true;
    std::uint32_t steps_without_boxes = 0;  ///< steps left before boxes are tried again
    std::vector<std::uint32_t> events;     ///< per body: events it took part in this step
    ProxySet proxies;                      ///< the bodies at the start of the step, widened by their reach
    BroadPhase broad_phase;                ///< finds the candidates once per step
    std::vector<BodyPair> pairs;           ///< candidates: widened bounding spheres overlap (in no order)
    std::vector<std::uint32_t> start;      ///< per body, into partners (a counting sort of pairs)
    std::vector<std::uint32_t> partners;   ///< each body's candidate partners, body after body
    std::vector<BodyPair> extra;           ///< candidates found later, for a body that outran its reach
    /// The same by body: extra_head[i] is body i's first node (or none), each node a partner.
    std::vector<std::uint32_t> extra_head;
    /// One later candidate of a body: a node of that body's list.
    struct ExtraNode {
        std::uint32_t partner;  ///< the other body
        std::uint32_t next;     ///< the body's next node, or none
    };
    std::vector<ExtraNode> extra_nodes;    ///< the nodes of every body's list of later candidates
    std::vector<std::uint32_t> near;       ///< bodies_near()'s answer
    std::vector<std::uint32_t> moving_planes;  ///< the kinematic planes that move or turn this step
    /// Per body at the end of the step: a sphere's centre and radius (radius -1 for other shapes).
    std::vector<SphereEnd> ends;
    std::vector<BodyPair> all_pairs;       ///< the candidates that overlap at the end of the step, sorted
    /// The events of the slice of the step opened last (see slice_head), as it was opened:
    /// sorted, earliest (then smallest pair) first, and taken from the front (run_next).
    std::vector<ImpactEvent> run;
    std::size_t run_next = 0;              ///< the first event of `run` not taken yet
    /// The events predicted into slices already opened, a heap: earliest (then smallest pair)
    /// first. The next event is the earlier of its top and run[run_next].
    std::vector<ImpactEvent> heap;
    /// The pending events of the later slices of the step: the step is cut into equal slices
    /// of time, and slice_head[b] is the first node of slice b's list (or none), each node an
    /// event and the next node. A slice's events are sorted only when its time comes, so that
    /// a sort or a heap holds a slice's events rather than the step's: in a pile of 10,000 a pop
    /// sifted through about 12 levels of a heap of thousands, a tenth of the event-timed step.
    /// A slice is sorted once rather than kept as a heap: in the bench's pile, whose columns
    /// bounce together, hundreds of impacts share a moment and a slice, and popping them from a
    /// heap compared their times, equal, at every level.
    std::vector<std::uint32_t> slice_head;
    /// A pending event of a later slice: a node of its slice's list.
    struct PendingEvent {
        ImpactEvent event;   ///< the event
        std::uint32_t next;  ///< the slice's next node, or none
    };
    std::vector<PendingEvent> pending;     ///< the nodes of every slice's list
    std::vector<Contact> contacts;         ///< the contacts answered at their moment this step
};

/// How bodies move between impacts over one step: x(tau) = x + v tau + k g tau^2 (the file comment).
struct EventMotion {
    Vector3 gravity;  ///< m/s^2
    double k;         ///< gravity_position_factor() of the world's integrator
    double dt;        ///< the step, s
};

/// Whether and how a stage checks the bodies for non-finite numbers (guards.hpp).
struct FiniteCheck {
    bool on = true;                        ///< the world's check_finite setting
    std::span<const std::string> names;    ///< the bodies' names, or empty
    std::uint64_t step = 0;                ///< the step being taken, 1 for the first
};

/// What move_impact_to_impact() leaves for the rest of the step.
struct ImpactsAnswered {
    /// Kinetic energy the responses at impacts changed, J (0 unless measured: move_impact_to_impact()).
    double energy_change = 0.0;
    /// Every pair that overlaps at the end of the step, each once, sorted by (first, second),
    /// found among the pairs whose bodies came near each other (a view of the scratch, valid
    /// until the next step).
    std::span<const BodyPair> overlapping_pairs;
    bool used_grid = false;                ///< the candidates were found with a grid
};

/// Stage 1 of a step under event timing: moves `bodies` from impact to impact within the step,
/// answering each impact at its moment with the model's responder (the contacts answered are
/// left in scratch.contacts, in order), then every body to the end of the step. What still
/// overlaps then (deep initial overlaps, resting contacts, pairs left out of the event loop)
/// is the discrete stages' to answer, among ImpactsAnswered::overlapping_pairs. A step handles at
/// most a bounded number of events (two per body, and at most max_events_per_body for any one
/// body), after which the rest of it is discrete: a ball coming to rest on the ground bounces
/// infinitely often in a finite time, and no event loop can follow that. The energy the
/// responses change is measured only when `measure_energy` (Shortcuts::response_energy_probe).
ImpactsAnswered move_impact_to_impact(std::span<RigidBody> bodies, const EventMotion& motion, const ResponseModel& model,
                                      const FiniteCheck& check, EventScratch& scratch, bool measure_energy = true);

/// The same without a responder: nothing changes at an impact, so the bodies pass as the
/// discrete loop would and there are no events to follow; each moves the whole step.
void advance_whole_step(std::span<RigidBody> bodies, const EventMotion& motion);

/// The most events one body takes part in within a step; after that its contacts are left to
/// the discrete back-stop (a resting pile would otherwise spend the whole budget on bounces
/// too small to see).
inline constexpr std::uint32_t max_events_per_body = 16;

}  // namespace workbook
