#include "workbook/contact_solver.hpp"

#include <algorithm>
#include <cmath>

#include "workbook/probes.hpp"

namespace workbook {

namespace {

std::uint64_t pair_key(const Contact& contact) {
    return (static_cast<std::uint64_t>(contact.body1) << 32) | contact.body2;
}

/// Turns `body` by the small rotation `turn` (rad, world frame): q += 1/2 (turn, 0) q, then
/// renormalised, and its world inertia brought up to date.
void turn_by(RigidBody& body, const Vector3& turn) {
    const Quaternion& q = body.orientation;
    const Quaternion spin{0.0, turn.x, turn.y, turn.z};
    const Quaternion dq = spin * q;
    body.orientation = normalized(Quaternion{q.w + 0.5 * dq.w, q.x + 0.5 * dq.x, q.y + 0.5 * dq.y, q.z + 0.5 * dq.z});
    body.update_world_inertia();
}

/// The warm start of a model with friction (chapter 6): at every point the impulse the
/// same point accumulated last step, J = normal n + friction[0] t1 + friction[1] t2, with the
/// model's own tangents, applied as chapter 5's warm start applies it (+J on body 1, -J on
/// body 2, angular terms included). Done here rather than by the chapter's warm_start so that
/// the friction impulses are always applied along the tangents they were accumulated along.
void warm_start_with_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses,
                              std::array<Vector3, 2> (*tangents)(const Vector3&)) {
    const auto [t1, t2] = tangents(contact.normal);
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const PointImpulse& p = impulses.points[i];
        const Vector3 j = p.normal * contact.normal + p.friction[0] * t1 + p.friction[1] * t2;
        if (j == Vector3{}) continue;
        const Vector3& at = contact.points[i].position;
        body1.velocity += body1.inverse_mass * j;
        body1.angular_velocity += body1.inverse_inertia_world * cross(at - body1.position, j);
        body2.velocity -= body2.inverse_mass * j;
        body2.angular_velocity -= body2.inverse_inertia_world * cross(at - body2.position, j);
    }
}

/// A soft contact over a substep h: the point acts as a spring of angular frequency w and
/// damping ratio z for its own effective mass, solved implicitly over h. A pass then aims at
/// the velocity bias_rate * s (s the signed gap, < 0 when overlapping), with the point's mass
/// scaled by mass_scale, and takes back impulse_scale of the impulse accumulated so far: the
/// three numbers of the implicit spring (Erin Catto's "soft step", Box2D v3).
struct Softness {
    double bias_rate = 0.0;      ///< 1/s
    double mass_scale = 1.0;     ///< share of the rigid impulse applied
    double impulse_scale = 0.0;  ///< share of the accumulated impulse taken back per pass
};

Softness soft_contact(double hertz, double damping_ratio, double h) {
    const double omega = 2.0 * 3.14159265358979323846 * hertz;
    const double a1 = 2.0 * damping_ratio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

/// The contacts as the chapter's functions may see them: a speculative point (negative depth,
/// the pair still apart by that much) with depth 0, so that its bias is 0 and every depth is
/// in the functions' legal domain. The solver sets such a point's target itself.
void clamp_depths(Contact& contact) {
    for (std::size_t i = 0; i < contact.point_count; ++i)
        contact.points[i].penetration = std::max(contact.points[i].penetration, 0.0);
}

std::span<const Contact> clamp_depths(std::span<const Contact> contacts, std::vector<Contact>& seen) {
    seen.assign(contacts.begin(), contacts.end());
    for (Contact& contact : seen) clamp_depths(contact);
    return seen;
}

/// The normal velocity of body 1 against body 2 at `at`, m/s (< 0: approaching).
double normal_velocity_at(const RigidBody& body1, const RigidBody& body2, const Vector3& at, const Vector3& normal) {
    const Vector3 v1 = body1.velocity + cross(body1.angular_velocity, at - body1.position);
    const Vector3 v2 = body2.velocity + cross(body2.angular_velocity, at - body2.position);
    return dot(v1 - v2, normal);
}

/// Whether a speculative point, apart by `gap` at detection and at normal velocity `u0` before
/// the solve, bounces in this step: it would meet its partner in the next move, and comes fast
/// enough to bounce (`bounce`, prepare()'s target from its depth of 0, is positive).
bool speculative_point_bounces(double bounce, double u0, double gap, double dt) { return bounce > 0.0 && u0 * dt < -gap; }

using PassFunction = double (*)(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses);

/// One pass of the chapter's `solve` (and `then`, unless null, on the same contact) over
/// `contacts` in their order, `pairs` their bodies' places among `bodies`; the largest change
/// they return. Its own function with everything it reads passed by value: the passes call
/// the chapter hundreds of times a step for every contact, and the loop around those calls
/// otherwise reloaded the solver's members around every one.
double one_pass(PassFunction solve, PassFunction then, std::span<RigidBody> bodies, std::span<const Contact> contacts,
                std::span<const std::array<std::uint32_t, 2>> pairs, std::span<ContactImpulses> impulses) {
    double largest = 0.0;
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        RigidBody& body1 = bodies[pairs[c][0]];
        RigidBody& body2 = bodies[pairs[c][1]];
        largest = std::max(largest, solve(body1, body2, contacts[c], impulses[c]));
        if (then != nullptr) largest = std::max(largest, then(body1, body2, contacts[c], impulses[c]));
    }
    return largest;
}

}  // namespace

std::array<Vector3, 2> friction_tangents(const Vector3& normal) {
    // Cross the normal with the axis it is least aligned with: never a short vector.
    const double ax = std::abs(normal.x), ay = std::abs(normal.y), az = std::abs(normal.z);
    const Vector3 axis = ax <= ay && ax <= az ? Vector3{1, 0, 0} : ay <= az ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
    const Vector3 t1 = normalized(cross(normal, axis));
    return {t1, cross(normal, t1)};
}

namespace {

/// Whether `body` has no corners or edges (a sphere or a plane): its contacts have one point,
/// which slides with the bodies and never jumps to another feature.
bool smooth(const RigidBody& body) { return body.shape.kind == ShapeKind::sphere || body.shape.kind == ShapeKind::plane; }

}  // namespace

void ContactSolver::recall(std::span<const RigidBody> bodies, std::span<const Contact> contacts, std::span<ContactImpulses> impulses_of,
                           const ContactSolverSettings& settings, ContactSolverReport& report) {
    const double reach2 = settings.match_distance * settings.match_distance;
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const Contact& contact = contacts[c];
        ContactImpulses& impulses = impulses_of[c];
        if (!settings.warm_start || previous_.empty()) continue;
        const auto found = std::lower_bound(previous_.begin(), previous_.end(), pair_key(contact),
                                            [](const Remembered& r, std::uint64_t key) { return r.pair < key; });
        if (found == previous_.end() || found->pair != pair_key(contact)) continue;
        // A pair whose normal turned a lot (two balls that passed each other) starts afresh.
        if (dot(found->normal, contact.normal) < 0.9) continue;
        // Two smooth bodies touch at one point, the same point however far it slid since the
        // last step: it is found by the pair, not by where it lies. Matched by distance, the
        // point of a ball sliding faster than match_distance a step started cold while the
        // other contacts of the same ball kept their impulses; in a pile, whose force chains
        // carry tens of balls' weight, that warm start kicked the ball by the unmatched
        // neighbour's share (docs/performance.md).
        if (smooth(bodies[contact.body1]) && smooth(bodies[contact.body2]) && contact.point_count == 1 && found->point_count == 1) {
            impulses.points[0].normal = found->normal_impulses[0];
            impulses.points[0].friction = found->friction_impulses[0];
            ++report.warm_started_points;
            continue;
        }
        for (std::size_t i = 0; i < contact.point_count; ++i) {
            double nearest = reach2;
            for (std::size_t k = 0; k < found->point_count; ++k) {
                const Vector3 d = contact.points[i].position - found->positions[k];
                const double d2 = dot(d, d);
                if (d2 < nearest) {
                    nearest = d2;
                    impulses.points[i].normal = found->normal_impulses[k];
                    impulses.points[i].friction = found->friction_impulses[k];
                }
            }
            if (nearest < reach2) ++report.warm_started_points;
        }
    }
}

void ContactSolver::remember(std::span<const Contact> contacts) {
    // Sorted by pair for recall()'s search: the keys alone, then the contacts copied in their
    // order (a Remembered is some 230 bytes; sorting those moved each about twenty times).
    sort_keys_.resize(contacts.size());
    for (std::size_t c = 0; c < contacts.size(); ++c) sort_keys_[c] = {pair_key(contacts[c]), static_cast<std::uint64_t>(c)};
    std::sort(sort_keys_.begin(), sort_keys_.end());
    current_.clear();
    for (const auto& [key, c] : sort_keys_) {
        const Contact& contact = contacts[c];
        Remembered& r = current_.emplace_back();
        r.pair = pair_key(contact);
        r.normal = contact.normal;
        r.point_count = contact.point_count;
        for (std::size_t i = 0; i < contact.point_count; ++i) {
            r.positions[i] = contact.points[i].position;
            r.normal_impulses[i] = impulses_[c].points[i].normal;
            r.friction_impulses[i] = impulses_[c].points[i].friction;
        }
    }
    std::swap(previous_, current_);
}

void ContactSolver::keep_for_waking(std::span<const Contact> contacts) {
    if (contacts.empty()) return;
    // remember() left this step's solved pairs in previous_, sorted; the pairs kept here are
    // looked up in current_, which still holds the step before (it is the scratch remember()
    // swapped out), and appended; then previous_ is sorted again.
    const std::size_t solved = previous_.size();
    for (const Contact& contact : contacts) {
        const auto found = std::lower_bound(current_.begin(), current_.end(), pair_key(contact),
                                            [](const Remembered& r, std::uint64_t key) { return r.pair < key; });
        if (found != current_.end() && found->pair == pair_key(contact)) previous_.push_back(*found);
    }
    if (previous_.size() > solved)
        std::sort(previous_.begin(), previous_.end(), [](const Remembered& a, const Remembered& b) { return a.pair < b.pair; });
}

void ContactSolver::reserve(std::size_t contacts) {
    if (impulses_.capacity() >= contacts) return;
    impulses_.reserve(contacts);
    adjusted_.reserve(contacts);
    seen_.reserve(contacts);
    staged_.reserve(contacts);
    staged_impulses_.reserve(contacts);
    rank_.reserve(contacts);
    pairs_.reserve(contacts);
    order_.reserve(contacts);
    height_.reserve(contacts);
    previous_.reserve(contacts);
    current_.reserve(contacts);
    sort_keys_.reserve(contacts);
    soft_points_.reserve(contacts * max_contact_points);
    bounces_.reserve(contacts * max_contact_points);
    gap_target_.reserve(contacts * max_contact_points);
}

void ContactSolver::order_passes(std::span<const Contact> contacts, const Vector3& up) {
    // The order of the passes: from the bottom up against gravity, by the height of each
    // contact's points, so that the weight of a stack reaches the ground in the first pass
    // (the ground's contact under a ball comes before the contact on top of that ball). Ties
    // keep detection's order.
    order_.resize(contacts.size());
    height_.resize(contacts.size());
    for (std::uint32_t c = 0; c < contacts.size(); ++c) {
        order_[c] = c;
        double sum = 0.0;
        for (std::size_t i = 0; i < contacts[c].point_count; ++i) sum += dot(contacts[c].points[i].position, up);
        height_[c] = contacts[c].point_count > 0 ? sum / contacts[c].point_count : 0.0;
    }
    // Ties broken by index: the order of a stable sort, without the buffer std::stable_sort
    // allocates (a warm step allocates nothing).
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
        return height_[a] < height_[b] || (height_[a] == height_[b] && a < b);
    });
}

void ContactSolver::stage(std::span<const Contact> contacts, bool speculative) {
    rank_.resize(contacts.size());
    staged_.resize(contacts.size());
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        rank_[order_[c]] = static_cast<std::uint32_t>(c);
        staged_[c] = contacts[order_[c]];
        if (speculative) clamp_depths(staged_[c]);
    }
    staged_impulses_.assign(contacts.size(), ContactImpulses{});
}

std::span<RigidBody> ContactSolver::gather(std::span<const RigidBody> bodies) {
    constexpr std::uint32_t none = ~std::uint32_t{0};
    local_.assign(bodies.size(), none);
    // Reserved for every body of the world: a warm step allocates nothing however many it touches.
    global_.reserve(bodies.size());
    staged_bodies_.reserve(bodies.size());
    saved_velocity_.reserve(bodies.size());
    saved_angular_velocity_.reserve(bodies.size());
    global_.clear();
    staged_bodies_.clear();
    pairs_.resize(staged_.size());
    for (std::size_t c = 0; c < staged_.size(); ++c) {
        for (const std::uint32_t b : {staged_[c].body1, staged_[c].body2})
            if (local_[b] == none) {
                local_[b] = static_cast<std::uint32_t>(global_.size());
                global_.push_back(b);
                staged_bodies_.push_back(bodies[b]);
            }
        pairs_[c] = {local_[staged_[c].body1], local_[staged_[c].body2]};
    }
    return staged_bodies_;
}

void ContactSolver::put_back(std::span<RigidBody> bodies) {
    for (std::size_t b = 0; b < staged_bodies_.size(); ++b) bodies[global_[b]] = staged_bodies_[b];
    impulses_.resize(staged_impulses_.size());
    for (std::size_t c = 0; c < staged_impulses_.size(); ++c) impulses_[order_[c]] = staged_impulses_[c];
}

ContactSolverReport ContactSolver::solve(std::span<RigidBody> bodies, std::span<const Contact> contacts,
                                         const ContactSolverHooks& hooks, const ContactSolverSettings& settings,
                                         const PositionCorrection& knobs, double dt, const Vector3& up,
                                         const Vector3& gravity, double gravity_position_factor,
                                         std::span<const std::uint8_t> woken) {
    ContactSolverReport report;
    // With speculative contacts the chapter's functions get the contacts with every depth at
    // least 0 (`seen`); the gaps are read from `contacts`.
    const bool speculative = settings.speculative_distance > 0.0;
    if (settings.substeps > 0) {
        impulses_.assign(contacts.size(), ContactImpulses{});
        recall(bodies, contacts, impulses_, settings, report);
        const std::span<const Contact> seen = speculative ? clamp_depths(contacts, seen_) : contacts;
        solve_in_substeps(bodies, contacts, seen, hooks, settings, knobs, dt, gravity, gravity_position_factor, woken, report);
        remember(contacts);
        return report;
    }

    order_passes(contacts, up);
    // The passes, hundreds a step, read the contacts, their impulses and their bodies front to
    // back: copies in the order of the passes, not scattered over detection's list and the
    // world's bodies, where a pile's passes spent much of their time waiting on memory.
    stage(contacts, speculative);
    recall(bodies, staged_, staged_impulses_, settings, report);
    solve_staged(gather(bodies), contacts, hooks, settings, knobs, dt, up, report);
    put_back(bodies);
    remember(contacts);
    return report;
}

void ContactSolver::solve_staged(std::span<RigidBody> bodies, std::span<const Contact> contacts, const ContactSolverHooks& hooks,
                                 const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt,
                                 const Vector3& up, ContactSolverReport& report) {
    const bool speculative = settings.speculative_distance > 0.0;
    const std::span<const Contact> seen = staged_;
    const std::span<ContactImpulses> impulses = staged_impulses_;
    // The two bodies of the contact in place c of the passes.
    auto first = [&](std::size_t c) -> RigidBody& { return bodies[pairs_[c][0]]; };
    auto second = [&](std::size_t c) -> RigidBody& { return bodies[pairs_[c][1]]; };

    // The velocities before the solve: its change of them also moves the bodies (below).
    saved_velocity_.resize(bodies.size());
    saved_angular_velocity_.resize(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        saved_velocity_[b] = bodies[b].velocity;
        saved_angular_velocity_[b] = bodies[b].angular_velocity;
    }

    // 1. What each point aims for, computed once from the velocities before any impulse.
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const Contact& contact = seen[c];
        hooks.prepare(first(c), second(c), contact, impulses[c], settings, knobs, dt);
    }
    // A speculative point, apart by s at detection: this solve moves the bodies by its change
    // of their velocities times dt (below), so the pair ends the step apart by
    // s + (u - u0) dt, u0 its normal velocity before the solve and u after. The target
    // max(u0, 0) - s / dt keeps that at least 0 (at least -u0 dt, what the pair approached
    // by in the move, when it approached): the gap may close, never turn into overlap. It asks
    // for nothing until the solve pushes the pair together faster than that, so a pair that
    // never meets is left as it is. A pair that approaches faster than s / dt would meet in the
    // next move: if it comes fast enough to bounce (prepare() gave it a bounce, from its depth
    // of 0), it bounces now, a gap s short of touching, as Box2D's speculative points do.
    // Stopped at the gap instead, it would arrive touching at s / dt, and bounce back at that
    // speed, not its own: a ball with e = 1 dropped from 1 m kept a tenth of its energy.
    gap_target_.assign(contacts.size() * max_contact_points, 0);
    if (speculative) {
        for (std::size_t c = 0; c < contacts.size(); ++c) {
            const Contact& contact = contacts[order_[c]];
            const RigidBody& body1 = first(c);
            const RigidBody& body2 = second(c);
            for (std::size_t i = 0; i < contact.point_count; ++i) {
                const double gap = -contact.points[i].penetration;
                if (!(gap > 0.0)) continue;
                const double u0 = normal_velocity_at(body1, body2, contact.points[i].position, contact.normal);
                if (speculative_point_bounces(impulses[c].points[i].bounce, u0, gap, dt)) continue;
                impulses[c].points[i].bounce = std::max(u0, 0.0) - gap / dt;
                gap_target_[c * max_contact_points + i] = 1;
            }
        }
    }
    // In detection's order: the impulses add up on each body in the order they come.
    if (settings.warm_start) {
        const bool with_friction = hooks.solve_friction != nullptr && hooks.tangents != nullptr;
        for (std::size_t detected = 0; detected < contacts.size(); ++detected) {
            const std::uint32_t c = rank_[detected];
            const Contact& contact = seen[c];
            if (with_friction)
                warm_start_with_friction(first(c), second(c), contact, impulses[c], hooks.tangents);
            else
                hooks.warm_start(first(c), second(c), contact, impulses[c]);
        }
    }

    // 2. Sequential impulses over all contacts until no point's velocity changes any more.
    //
    // With friction, in two phases (chapter 6): first the contacts stop approaching (target
    // normal velocity 0) with friction, then the bounce is added along the normal alone.
    // Newton's restitution solved together with friction can create energy: at a point off
    // the centre of mass (a rod landing on its end) friction changes the normal velocity too,
    // and aiming the normal pass at -e u then returns more than the impact brought. Solved
    // apart, the bounce gives back at most e^2 of what stopping the approach took.
    // Only where friction acts: without it the bounce comes as in chapter 5, in one phase.
    bool two_phases = false;
    for (std::size_t c = 0; c < contacts.size() && hooks.solve_friction != nullptr && !two_phases; ++c)
        two_phases = first(c).static_friction * second(c).static_friction > 0.0;
    bool any_bounce = false;
    if (two_phases) {
        bounces_.resize(contacts.size() * max_contact_points);
        for (std::size_t c = 0; c < contacts.size(); ++c)
            for (std::size_t i = 0; i < max_contact_points; ++i) {
                double& bounce = impulses[c].points[i].bounce;
                bounces_[c * max_contact_points + i] = bounce;
                // A gap's target is no bounce: it holds in both phases, whatever its sign (a
                // pair that separates faster than its gap closes in a step has a positive one).
                if (gap_target_[c * max_contact_points + i] != 0) continue;
                any_bounce = any_bounce || bounce != 0.0;
                bounce = 0.0;
            }
    }
    auto velocity_passes = [&](bool with_friction) {
        for (int pass = 0; pass < settings.velocity_iterations; ++pass) {
            const double largest =
                one_pass(hooks.solve_velocity, with_friction ? hooks.solve_friction : nullptr, bodies, seen, pairs_, impulses);
            ++report.velocity_passes;
            report.velocity_residual = largest;
            if (!(largest > settings.tolerance)) break;
        }
    };
    velocity_passes(hooks.solve_friction != nullptr);
    if (any_bounce) {
        for (std::size_t c = 0; c < contacts.size(); ++c)
            for (std::size_t i = 0; i < max_contact_points; ++i) impulses[c].points[i].bounce = bounces_[c * max_contact_points + i];
        velocity_passes(false);
    }

    // Shock propagation (settings.shock_sweeps): sweeps from the bottom up in which a contact
    // that leans out of the horizontal pushes its upper body alone, the lower one frozen for
    // that contact (its inverse mass and inertia zero while the chapter's functions run; the
    // point's mass then comes from the chapter's prepare() for that frozen pair). Which body
    // is lower comes from the contact's normal, not from levels of a search through the
    // contacts outward from the immovable bodies: the walls of a box are immovable at every
    // height, so such a search puts every disc against a wall on the first level however
    // high it is, below the discs it rests on, and the sweep would push those down into the
    // pile instead of the disc up. `up` is -gravity, not a unit vector.
    const double up_length = length(up);
    // The sweep calls the chapter's functions as the passes do: the normal impulse, then,
    // where friction acts, friction within the cone of that normal impulse.
    auto solve_contact = [&](RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& contact_impulses,
                             bool rubs) {
        double largest = hooks.solve_velocity(body1, body2, contact, contact_impulses);
        if (rubs) largest = std::max(largest, hooks.solve_friction(body1, body2, contact, contact_impulses));
        return largest;
    };
    // A contact of one movable body (against an immovable body, or a frozen lower one) is
    // that body's problem alone, and is solved to the passes' tolerance: a face's points and
    // their friction share the body's spin, so one call leaves part of each point's change to
    // the next (a box on a box has four points; a tall stack of boxes with friction, each
    // left a little turning, topples). A lone point without friction is exact in one call.
    auto solve_one_body_contact = [&](RigidBody& body1, RigidBody& body2, const Contact& contact,
                                      ContactImpulses& contact_impulses, bool rubs) {
        for (int call = 1;; ++call)
            if (!(solve_contact(body1, body2, contact, contact_impulses, rubs) > settings.tolerance) ||
                (contact.point_count == 1 && !rubs) || call >= std::max(settings.velocity_iterations, 1))
                return;
    };
    auto bounces_at = [&](std::size_t c) {
        for (std::size_t i = 0; i < max_contact_points; ++i) {
            const std::size_t k = c * max_contact_points + i;
            if (gap_target_[k] == 0 && bounces_[k] > 0.0) return true;
        }
        return false;
    };
    auto shock_sweep = [&](std::span<const Contact> list) {
        for (std::size_t c = 0; c < list.size(); ++c) {
            const Contact& contact = list[c];
            RigidBody& body1 = first(c);
            RigidBody& body2 = second(c);
            const bool rubs = hooks.solve_friction != nullptr && body1.static_friction * body2.static_friction > 0.0;
            // A rubbing contact that bounces got its bounce along the normal alone, after its
            // friction (the second phase above): friction again would undo that order.
            if (rubs && any_bounce && bounces_at(c)) continue;
            // The normal points from body 2 to body 1: a positive lean puts body 1 above.
            const double lean = up_length > 0.0 ? dot(contact.normal, up) / up_length : 0.0;
            RigidBody* lower = nullptr;
            RigidBody* upper = nullptr;
            if (!body1.is_immovable() && !body2.is_immovable()) {
                if (lean > settings.shock_slope) {
                    lower = &body2;
                    upper = &body1;
                } else if (lean < -settings.shock_slope) {
                    lower = &body1;
                    upper = &body2;
                }
            }
            ContactImpulses& contact_impulses = impulses[c];
            if (lower == nullptr) {
                if (body1.is_immovable() || body2.is_immovable())
                    solve_one_body_contact(body1, body2, contact, contact_impulses, rubs);
                else
                    solve_contact(body1, body2, contact, contact_impulses, rubs);
                continue;
            }
            const ContactImpulses saved = contact_impulses;
            const double inverse_mass = lower->inverse_mass;
            const Matrix3 inverse_inertia = lower->inverse_inertia_world;
            lower->inverse_mass = 0.0;
            lower->inverse_inertia_world = Matrix3::zero();
            // prepare() fills the frozen pair's masses; what else it sets (bounce, bias, the
            // pseudo-impulse) comes back from before, since it would be computed from the
            // velocities the passes have changed.
            hooks.prepare(body1, body2, contact, contact_impulses, settings, knobs, dt);
            for (std::size_t i = 0; i < contact.point_count; ++i) {
                const double mass = contact_impulses.points[i].mass;
                contact_impulses.points[i] = saved.points[i];
                contact_impulses.points[i].mass = mass;
            }
            const Vector3 velocity = upper->velocity, angular_velocity = upper->angular_velocity;
            const double before = kinetic_energy(*upper);
            solve_one_body_contact(body1, body2, contact, contact_impulses, rubs);
            lower->inverse_mass = inverse_mass;
            lower->inverse_inertia_world = inverse_inertia;
            for (std::size_t i = 0; i < contact.point_count; ++i) contact_impulses.points[i].mass = saved.points[i].mass;
            // Only the upper body changed: if it gained kinetic energy (its lower neighbour
            // moves into it faster than it comes down), the contact is solved two-sided.
            if (kinetic_energy(*upper) > before) {
                upper->velocity = velocity;
                upper->angular_velocity = angular_velocity;
                contact_impulses = saved;
                solve_contact(body1, body2, contact, contact_impulses, rubs);
            }
        }
    };
    for (int sweep = 0; sweep < settings.shock_sweeps; ++sweep) shock_sweep(seen);

    // The move of this step used the velocities before the solve; the solve's change of them
    // belongs to this step too (as when the solve comes before the move, the order of Box2D
    // and Chipmunk): each body moves by that change times dt, and each point's depth is
    // estimated after that move. A resting stack then does not sink by g dt^2 a step.
    adjusted_.resize(contacts.size());
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        Contact& contact = adjusted_[c] = contacts[order_[c]];
        const RigidBody& body1 = first(c);
        const RigidBody& body2 = second(c);
        const Vector3 dv1 = body1.velocity - saved_velocity_[pairs_[c][0]], dw1 = body1.angular_velocity - saved_angular_velocity_[pairs_[c][0]];
        const Vector3 dv2 = body2.velocity - saved_velocity_[pairs_[c][1]], dw2 = body2.angular_velocity - saved_angular_velocity_[pairs_[c][1]];
        contact.penetration = 0.0;
        for (std::size_t i = 0; i < contact.point_count; ++i) {
            ContactPoint& point = contact.points[i];
            const Vector3 change1 = dv1 + cross(dw1, point.position - body1.position);
            const Vector3 change2 = dv2 + cross(dw2, point.position - body2.position);
            point.penetration = std::max(point.penetration - dot(change1 - change2, contact.normal) * dt, 0.0);
            // The point moves with the bodies (halfway between the two material points), so
            // that its lever arms stay those of the contact: a ball's along the normal.
            const Vector3 shift = body1.is_immovable() ? change2 : body2.is_immovable() ? change1 : 0.5 * (change1 + change2);
            point.position += shift * dt;
            contact.penetration = std::max(contact.penetration, point.penetration);
        }
    }
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        RigidBody& body = bodies[b];
        if (body.is_immovable()) continue;
        const Vector3 dv = body.velocity - saved_velocity_[b], dw = body.angular_velocity - saved_angular_velocity_[b];
        if (dv != Vector3{}) body.position += dv * dt;
        if (dw != Vector3{}) turn_by(body, dw * dt);
    }

    // 3. The overlap, on pseudo-velocities: every body swaps its velocities for zero ones, the
    // position passes push those apart, the bodies move by them over dt, and the real
    // velocities come back untouched. Kinetic energy cannot change here.
    for (std::size_t c = 0; c < adjusted_.size(); ++c) {
        const Contact& contact = adjusted_[c];
        hooks.prepare(first(c), second(c), contact, impulses[c], settings, knobs, dt);
    }
    bool any_bias = false;
    for (std::size_t c = 0; c < contacts.size() && !any_bias; ++c)
        for (std::size_t i = 0; i < seen[c].point_count; ++i) any_bias = any_bias || impulses[c].points[i].bias > 0.0;
    if (any_bias && settings.position_iterations > 0) {
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            saved_velocity_[b] = bodies[b].velocity;
            saved_angular_velocity_[b] = bodies[b].angular_velocity;
            bodies[b].velocity = bodies[b].angular_velocity = Vector3{};
        }
        for (int pass = 0; pass < settings.position_iterations; ++pass) {
            const double largest = one_pass(hooks.solve_position, nullptr, bodies, adjusted_, pairs_, impulses);
            report.position_passes = pass + 1;
            report.position_residual = largest;
            if (!(largest > settings.tolerance)) break;
        }
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            RigidBody& body = bodies[b];
            if (!body.is_immovable()) {
                if (body.velocity != Vector3{}) body.position += body.velocity * dt;
                if (body.angular_velocity != Vector3{}) turn_by(body, body.angular_velocity * dt);
            }
            body.velocity = saved_velocity_[b];
            body.angular_velocity = saved_angular_velocity_[b];
        }
    }
}

void ContactSolver::solve_in_substeps(std::span<RigidBody> bodies, std::span<const Contact> detected,
                                      std::span<const Contact> contacts, const ContactSolverHooks& hooks,
                                      const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt, const Vector3& gravity,
                                      double gravity_position_factor, std::span<const std::uint8_t> woken,
                                      ContactSolverReport& report) {
    const int n = settings.substeps;
    const double h = dt / n;
    // Stiffer than a quarter of the substep rate the spring would not be resolved by a substep.
    const Softness soft = soft_contact(std::min(settings.contact_hertz, 0.25 / h), settings.contact_damping_ratio, h);
    const double max_push_speed = settings.max_push / dt;
    const bool with_friction = hooks.solve_friction != nullptr;

    // What each point aims for, from the velocities the world's move left (the bounce is the
    // approach it saw), and the lever arms, fixed over the step.
    soft_points_.resize(contacts.size() * max_contact_points);
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const Contact& contact = contacts[c];
        const RigidBody& body1 = bodies[contact.body1];
        const RigidBody& body2 = bodies[contact.body2];
        hooks.prepare(body1, body2, contact, impulses_[c], settings, knobs, dt);
        for (std::size_t i = 0; i < contact.point_count; ++i) {
            SoftPoint& sp = soft_points_[c * max_contact_points + i];
            sp.mass = impulses_[c].points[i].mass;
            // The depth as detected: a speculative point's is negative (contacts, the chapter's
            // view, has it at 0), and aim() lets it approach by its gap; it bounces only when
            // it meets its partner within the step fast enough to (as in solve_staged()).
            sp.depth = detected[c].points[i].penetration;
            const bool apart = settings.speculative_distance > 0.0 && sp.depth < 0.0;
            sp.bounce = impulses_[c].points[i].bounce;
            if (apart && !speculative_point_bounces(sp.bounce, normal_velocity_at(body1, body2, contact.points[i].position, contact.normal),
                                                    -sp.depth, dt))
                sp.bounce = 0.0;
            sp.r1 = contact.points[i].position - body1.position;
            sp.r2 = contact.points[i].position - body2.position;
        }
    }

    // The bodies of the contacts go back to the start of the step: the world moved them by
    // the whole step and gave them gravity's whole kick; the substeps give both again, in
    // n shares. Their move is kept apart (shift, turn) and made at the end; detection's
    // points and lever arms stay where they were found. A body that woke after the move got
    // neither, and starts where it stands.
    const std::size_t count = bodies.size();
    shift_.assign(count, Vector3{});
    turn_.assign(count, Vector3{});
    touched_.assign(count, 0);
    for (const Contact& contact : contacts) {
        touched_[contact.body1] = bodies[contact.body1].is_immovable() ? 0 : 1;
        touched_[contact.body2] = bodies[contact.body2].is_immovable() ? 0 : 1;
    }
    const Vector3 kick = gravity * dt;
    const Vector3 gravity_move = gravity * ((1.0 - gravity_position_factor) * dt * dt);
    for (std::size_t b = 0; b < count; ++b) {
        if (touched_[b] == 0 || (!woken.empty() && woken[b] != 0)) continue;
        RigidBody& body = bodies[b];
        shift_[b] = -(body.velocity * dt - gravity_move);
        turn_[b] = -(body.angular_velocity * dt);
        body.velocity -= kick;
    }

    // The signed gap of a point now (< 0: overlap): detection's depth, changed by how far
    // the two material points have moved along the normal since.
    auto gap = [&](const Contact& contact, std::size_t c, std::size_t i) {
        const SoftPoint& sp = soft_points_[c * max_contact_points + i];
        const Vector3 move1 = shift_[contact.body1] + cross(turn_[contact.body1], sp.r1);
        const Vector3 move2 = shift_[contact.body2] + cross(turn_[contact.body2], sp.r2);
        return -sp.depth + dot(move1 - move2, contact.normal);
    };
    // Sets each point's mass and target for the chapter's solve_velocity: a point apart
    // may approach by its gap within the substep; an overlapping one is a soft contact that
    // pushes out what exceeds the slop (`soft`, no faster than max_push a step), or, in the
    // relax passes, a rigid one that only stops the approach.
    auto aim = [&](const Contact& contact, std::size_t c, bool push) {
        for (std::size_t i = 0; i < contact.point_count; ++i) {
            const SoftPoint& sp = soft_points_[c * max_contact_points + i];
            PointImpulse& p = impulses_[c].points[i];
            p.mass = sp.mass;
            p.bounce = 0.0;
            if (sp.mass == 0.0) continue;
            const double s = gap(contact, c, i);
            if (s > 0.0) {
                p.bounce = -s / h;
            } else if (push) {
                const double bias = std::max(soft.bias_rate * std::min(s + knobs.slop, 0.0), -max_push_speed);
                p.mass = sp.mass * soft.mass_scale;
                p.bounce = -bias - soft.impulse_scale * p.normal / p.mass;
            }
        }
    };
    auto pass = [&](bool push) {
        for (std::size_t c = 0; c < contacts.size(); ++c) {
            const Contact& contact = contacts[c];
            RigidBody& body1 = bodies[contact.body1];
            RigidBody& body2 = bodies[contact.body2];
            aim(contact, c, push);
            hooks.solve_velocity(body1, body2, contact, impulses_[c]);
            if (with_friction) hooks.solve_friction(body1, body2, contact, impulses_[c]);
        }
        ++report.velocity_passes;
    };

    for (int k = 0; k < n; ++k) {
        for (std::size_t b = 0; b < count; ++b)
            if (touched_[b] != 0) bodies[b].velocity += gravity * h;
        // The impulses accumulated so far (the last step's at first) are each substep's.
        if (settings.warm_start || k > 0)
            for (std::size_t c = 0; c < contacts.size(); ++c) {
                const Contact& contact = contacts[c];
                if (with_friction && hooks.tangents != nullptr)
                    warm_start_with_friction(bodies[contact.body1], bodies[contact.body2], contact, impulses_[c], hooks.tangents);
                else
                    hooks.warm_start(bodies[contact.body1], bodies[contact.body2], contact, impulses_[c]);
            }
        pass(true);
        for (std::size_t b = 0; b < count; ++b) {
            if (touched_[b] == 0) continue;
            shift_[b] += bodies[b].velocity * h;
            turn_[b] += bodies[b].angular_velocity * h;
        }
        // One relax pass takes a lone contact's push back out exactly, but in a pile each
        // point's correction disturbs its neighbours' (settings.relax_passes).
        for (int relax = 0; relax < settings.relax_passes; ++relax) pass(false);
    }

    // The bounce, along the normals alone, after the substeps (as friction's second phase).
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const Contact& contact = contacts[c];
        bool bounces = false;
        for (std::size_t i = 0; i < contact.point_count; ++i) {
            const SoftPoint& sp = soft_points_[c * max_contact_points + i];
            impulses_[c].points[i].mass = sp.mass;
            impulses_[c].points[i].bounce = sp.bounce;
            bounces = bounces || sp.bounce > 0.0;
        }
        if (bounces) hooks.solve_velocity(bodies[contact.body1], bodies[contact.body2], contact, impulses_[c]);
    }

    for (std::size_t b = 0; b < count; ++b) {
        if (touched_[b] == 0) continue;
        RigidBody& body = bodies[b];
        if (shift_[b] != Vector3{}) body.position += shift_[b];
        if (turn_[b] != Vector3{}) turn_by(body, turn_[b]);
    }
}

}  // namespace workbook
