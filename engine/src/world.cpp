#include "workbook/world.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "workbook/detection.hpp"
#include "workbook/event_timing.hpp"
#include "workbook/guards.hpp"
#include "workbook/rotation.hpp"
#include "workbook/swept_spheres.hpp"

namespace workbook {

World::World(std::vector<RigidBody> bodies, WorldSettings settings, ResponseModel model)
    : bodies_(std::move(bodies)), settings_(settings), model_(model) {
    if (model_.contact_solver != nullptr && settings_.contact_timing == ContactTiming::event)
        throw std::invalid_argument("responder '" + std::string(model_.name) +
                                    "' solves all contacts of a step together and needs discrete contact timing");
    for (RigidBody& body : bodies_) body.update_world_inertia();
    // Contacts are stored in proportion to the contacts there are: room for one per body up
    // front (a resting pile has about one per body, the gas of bench/ 1.5% of one), then
    // doubling while a scene warms up; capacity is kept, so a warm step allocates nothing
    // (tests/engine/allocation.cpp). The broad phase's buffers grow the same way.
    contacts_.reserve(bodies_.size());
    // The broad phase sizes its buffers for this scene here, on the bodies as they stand (with
    // the swept test's data when it will run), so that the first step does not pay for growing
    // them, nor for the system's first touch of their memory (about 20 MB at N = 100,000).
    if (uses_grid()) {
        gather_proxies();
        proxies_.margin = contact_margin();
        // Not for bodies at non-finite positions: every pair would be listed.
        if (proxies_.poison == 0.0) broad_phase_.find_pairs(proxies_, pairs_, !shortcuts_.skip_immovable_pairs);
    }
}

void World::step() {
    if (settings_.contact_timing == ContactTiming::event) {
        // The bodies move from impact to impact, each answered at its moment; what still
        // overlaps at the end is answered as the discrete stages would.
        integrate_impact_to_impact();  // 1. to each impact in turn, answered there, then to the end
        detect();                      // 2. what still overlaps, among the pairs that came near
        respond();                     // 3. the model's velocity responder, once per contact
        correct();                     // 4. the model's position corrector, once per contact
        keep_answered_impacts();       // the impacts of 1 join the contacts and the energy probe
    } else {
        integrate();  // 1. gravity, then positions and orientations
        skipped_ = at_rest_ && !moved_;
        if (skipped_) {
            // Everything asleep where the last step found it: nothing to detect or solve.
            ++steps_;
            time_ += settings_.time_step;
            return;
        }
        at_rest_ = !moved_;
        detect();     // 2. overlapping pairs, and the swept test of fast spheres
        if (model_.contact_solver != nullptr) {
            solve_contacts();  // 3 and 4 together: every contact of the step, solved at once
        } else {
            respond();  // 3. the model's velocity responder, once per contact
            correct();  // 4. the model's position corrector, once per contact
        }
    }
    ++steps_;
    time_ += settings_.time_step;
}

void World::integrate_impact_to_impact() {
    const EventMotion motion{settings_.gravity, gravity_position_factor(settings_.integrator), settings_.time_step};
    proxies_fresh_ = false;
    impacts_ = {};
    event_scratch_.contacts.clear();
    if (model_.respond == nullptr) {
        event_scratch_.copies_known = false;  // the bodies move without the event loop
        advance_whole_step(bodies_, motion);
        guard("event: advance");
        return;
    }
    impacts_ = move_impact_to_impact(bodies_, motion, model_, {settings_.check_finite, body_names_, steps_ + 1}, event_scratch_,
                                     shortcuts_.response_energy_probe);
    impacts_fresh_ = true;
}

void World::keep_answered_impacts() {
    response_energy_change_ += impacts_.energy_change;
    // The contacts answered at their moment come first, in the order they were answered. Room
    // made first by doubling the capacity: an insert grows the vector to twice its size, which
    // in a pile whose contacts grow step by step was just over what it had, again and again.
    // detect() put them there already, unless the bodies were changed in between (bodies()).
    if (!impacts_placed_) {
        const std::size_t needed = contacts_.size() + event_scratch_.contacts.size();
        if (contacts_.capacity() < needed) contacts_.reserve(std::max(needed, 2 * contacts_.capacity()));
        contacts_.insert(contacts_.begin(), event_scratch_.contacts.begin(), event_scratch_.contacts.end());
    }
    impacts_placed_ = false;
    answered_first_ = 0;
}

void World::guard(const char* stage) const {
    if (settings_.check_finite) check_finite(bodies_, body_names_, steps_ + 1, stage);
}

void World::guard_bodies(const char* stage, std::span<const std::uint32_t> changed) const {
    if (!settings_.check_finite) return;
    double sum = 0.0;
    for (std::uint32_t i : changed) sum += poison(bodies_[i]);
    if (!(sum == 0.0)) check_finite(bodies_, body_names_, steps_ + 1, stage);
}

bool World::uses_grid() const { return shortcuts_.broad_phase && bodies_.size() >= shortcuts_.broad_phase_from; }

namespace {

bool has_gravity(const WorldSettings& settings, const Shortcuts& shortcuts) {
    return !shortcuts.skip_zero_gravity || settings.gravity != Vector3{};
}

}  // namespace

void World::integrate() {
    // With the grid, the same pass over the bodies copies what the broad phase reads into its
    // proxies (and the swept test's starts), for the detect() that follows: at N = 100,000 the
    // bodies (328 bytes each) fit in no cache, and a separate pass cost as much as the grid.
    const bool discrete = settings_.contact_timing == ContactTiming::discrete;
    const bool grid = discrete && uses_grid();
    event_scratch_.copies_known = false;  // the bodies move without the event loop
    const double poison = integrate_bodies(grid, grid && sweeps_spheres());
    proxies_fresh_ = grid;
    if (!(poison == 0.0)) guard("integrate");
}

double World::integrate_bodies(bool gather, bool swept) {
    const double dt = settings_.time_step;
    const Vector3 gravity_kick = settings_.gravity * dt;
    const bool gravity = has_gravity(settings_, shortcuts_);
    const bool semi_implicit = settings_.integrator == Integrator::semi_implicit_euler;
    const auto count = static_cast<std::uint32_t>(bodies_.size());
    const Vector3 gravity_term = start_gravity_term();
    if (gather) {
        proxies_.clear(count);
    }
    double smallest_radius = std::numeric_limits<double>::infinity();
    double sum = 0.0;
    bool moved = false;
    for (std::uint32_t i = 0; i < count; ++i) {
        RigidBody& body = bodies_[i];
        if (body.is_immovable()) {
            // Kinematic bodies move at their own constant velocity and spin; gravity and
            // contacts never change them (immovable ones have neither, and stay put).
            moved = moved || body.velocity != Vector3{} || body.angular_velocity != Vector3{};
            advance_kinematic(body, dt);
        } else if (sleeping_.asleep(i) && body.velocity == Vector3{} && body.angular_velocity == Vector3{}) {
            // A sleeping body stays where it is, at rest (workbook/sleeping.hpp); one that a
            // tool or test has given a velocity (through bodies()) wakes, and its island with it.
        } else {
            moved = true;
            sleeping_.wake(i);
            if (semi_implicit) {
                if (gravity) body.velocity += gravity_kick;
                body.position += body.velocity * dt;
            } else if (settings_.integrator == Integrator::exact_under_gravity) {
                body.position += body.velocity * dt + gravity_kick * (0.5 * dt);
                body.velocity += gravity_kick;
            } else {
                body.position += body.velocity * dt;
                if (gravity) body.velocity += gravity_kick;
            }
            if (!shortcuts_.skip_still_rotation || body.angular_velocity != Vector3{}) advance_free_rotation(body, dt);
        }
        sum += poison(body);
        if (gather) gather_body(i, swept, dt, gravity_term, smallest_radius);
    }
    if (gather && swept) {
        proxies_.swept = true;
        proxies_.fast_travel = smallest_radius;
    }
    moved_ = moved;
    return sum;
}

void World::gather_body(std::uint32_t i, bool swept, double dt, const Vector3& gravity_term, double& smallest_radius) {
    const RigidBody& body = bodies_[i];
    double travel = 0.0;
    Vector3 start{};
    if (swept) {
        // What the swept test needs of each sphere: where it started and how far it went.
        start = start_of_step(body, dt, gravity_term);
        if (body.shape.kind == ShapeKind::sphere) {
            travel = length(body.position - start);
            smallest_radius = std::min(smallest_radius, body.shape.radius);
        } else if (body.shape.kind == ShapeKind::box) {
            // A box is not traced, but a fast sphere's path must be met where the box went.
            travel = length(body.position - start);
        }
    }
    proxies_.add(body, i, travel, start);
}

void World::detect() {
    impacts_placed_ = false;
    answered_first_ = 0;
    if (impacts_fresh_) {
        // After integrate_impact_to_impact(), which found the overlapping pairs among those
        // whose bodies came near each other, in index order as below.
        impacts_fresh_ = false;
        // The impacts' contacts go first, where the step leaves them (keep_answered_impacts()),
        // put there now rather than moved in front of the pairs found below once the step is
        // answered: in a pile that moved two contacts per body every step. respond() and
        // correct() pass over them (they were answered at their moment). The two vectors trade
        // places rather than copy: the copy was 176 bytes per impact, a pile of 100,000 has
        // 55,000 a step, and the last step's contacts, no longer needed, leave room for the next
        // step's impacts.
        contacts_.swap(event_scratch_.contacts);
        event_scratch_.contacts.clear();
        answered_first_ = contacts_.size();
        impacts_placed_ = true;
        // Room for a contact per overlapping pair, twice over when it grows: the two vectors take
        // turns, and each must keep room for the impacts and the contacts of a step.
        const std::size_t needed = contacts_.size() + impacts_.overlapping_pairs.size();
        if (contacts_.capacity() < needed) contacts_.reserve(2 * needed);
        used_broad_phase_ = impacts_.used_grid;
        for (const auto [i, j] : impacts_.overlapping_pairs) add_contact_if_any(i, j);
        return;
    }
    // The proxies integrate() gathered, unless the bodies may have changed since.
    // Contacts found here may be answered by respond() and correct() between two event-timed
    // steps, among bodies the event loop does not know to have changed.
    event_scratch_.copies_known = false;
    find_contacts(proxies_fresh_);
    proxies_fresh_ = false;
    const bool swept = sweeps_spheres();
    if (swept) {
        const double dt = settings_.time_step;
        const Vector3 gravity_term = start_gravity_term();
        SweepGrid grid;
        if (used_broad_phase_ && broad_phase_.has_grid() && proxies_.swept) grid = {&proxies_, &broad_phase_};
        sweep_fast_spheres(bodies_, dt, gravity_term, grid, contacts_, sweep_scratch_);
    }
    // Only the spheres the swept test moved back changed here; the guard looks at those (and,
    // on a find, at all, to name the first in body order).
    guard_bodies("detect", swept ? std::span<const std::uint32_t>(sweep_scratch_.moved) : std::span<const std::uint32_t>());
}

void World::gather_proxies() {
    // As integrate() gathers them, with the swept test's starts and travels: the travels also
    // reach speculative contacts (speculative_reach()), which must not depend on which pass
    // gathered the proxies.
    const bool swept = sweeps_spheres();
    const auto count = static_cast<std::uint32_t>(bodies_.size());
    const double dt = settings_.time_step;
    const Vector3 gravity_term = start_gravity_term();
    double smallest_radius = std::numeric_limits<double>::infinity();
    proxies_.clear(count);
    for (std::uint32_t i = 0; i < count; ++i) gather_body(i, swept, dt, gravity_term, smallest_radius);
    proxies_.swept = swept;
    proxies_.fast_travel = smallest_radius;
}

void World::find_contacts(bool gathered) {
    contacts_.clear();
    used_broad_phase_ = uses_grid();
    if (used_broad_phase_) {
        if (!gathered) gather_proxies();
        proxies_.margin = contact_margin();
        broad_phase_.find_pairs(proxies_, pairs_, !shortcuts_.skip_immovable_pairs);
        for (const auto [i, j] : pairs_) add_contact_from_proxies(i, j);
        return;
    }
    const auto count = static_cast<std::uint32_t>(bodies_.size());
    for (std::uint32_t i = 0; i < count; ++i) {
        for (std::uint32_t j = i + 1; j < count; ++j) {
            if (shortcuts_.skip_immovable_pairs && bodies_[i].is_immovable() && bodies_[j].is_immovable()) continue;
            add_contact_if_any(i, j);
        }
    }
}

double World::contact_margin() const {
    return model_.contact_solver != nullptr && settings_.contact_timing == ContactTiming::discrete
               ? settings_.contact_solver.speculative_distance
               : 0.0;
}

bool World::sweeps_spheres() const {
    return settings_.contact_timing == ContactTiming::discrete && settings_.swept_spheres;
}

Vector3 World::start_gravity_term() const {
    const double dt = settings_.time_step;
    return settings_.gravity * ((1.0 - gravity_position_factor(settings_.integrator)) * dt * dt);
}

double World::travel_in_step(const RigidBody& body) const {
    if (!sweeps_spheres()) return 0.0;
    const double dt = settings_.time_step;
    const Vector3 gravity_term = start_gravity_term();
    return length(body.position - start_of_step(body, dt, gravity_term));  // as gather_body() has it
}

void World::add_contact_if_any(std::uint32_t i, std::uint32_t j) {
    const RigidBody& a = bodies_[i];
    const RigidBody& b = bodies_[j];
    const double margin = contact_margin();
    const double travel_a = margin > 0.0 ? travel_in_step(a) : 0.0, travel_b = margin > 0.0 ? travel_in_step(b) : 0.0;
    if (!overlaps(a, b) && !(margin > 0.0 && within_margin(a, b, margin, travel_a, travel_b))) return;
    // Two immovable bodies never get a contact: nothing could answer it.
    if (a.is_immovable() && b.is_immovable()) return;
    // The slot is reserved first so the contact is written in place; a box pair that the full
    // test finds apart (beyond the reach of speculative points) gives it back (pop_back keeps
    // the capacity: still no allocation).
    const double reach = margin > 0.0 ? speculative_reach(a, b, margin, travel_a, travel_b) : 0.0;
    if (!write_contact(a, i, b, j, contacts_.emplace_back(), reach)) contacts_.pop_back();
}

void World::add_contact_from_proxies(std::uint32_t i, std::uint32_t j) {
    // Spheres and planes are tested and written from the proxies, which hold the same numbers
    // as the bodies in 72 contiguous bytes: the pairs' bodies are not read at all (at
    // N = 100,000 each read of a body missed every cache). Boxes take the bodies' path.
    // Within the reach of speculative contacts (0 without them: the overlap test).
    const GridProxy& a = proxies_.proxies[i];
    const GridProxy& b = proxies_.proxies[j];
    const double margin = proxies_.margin;
    if (a.sphere && b.sphere) {
        const Vector3 centre1{a.x, a.y, a.z}, centre2{b.x, b.y, b.z};
        if (!spheres_overlap(centre1, a.radius + speculative_reach(margin, a.travel, b.travel), centre2, b.radius)) return;
        // Two immovable bodies never get a contact: nothing could answer it.
        if (!a.movable && !b.movable) return;
        Contact& contact = contacts_.emplace_back();
        write_spheres(centre1, a.radius, centre2, b.radius, contact);
        contact.body1 = i;
        contact.body2 = j;
        return;
    }
    if ((a.sphere && b.plane) || (a.plane && b.sphere)) {
        const GridProxy& sphere = a.sphere ? a : b;
        const PlaneProxy& plane = *std::lower_bound(proxies_.planes.begin(), proxies_.planes.end(), a.plane ? i : j, plane_before);
        const Vector3 centre{sphere.x, sphere.y, sphere.z};
        if (!sphere_plane_overlap(centre, sphere.radius + margin, plane.point, plane.normal)) return;
        if (!sphere.movable && !plane.movable) return;
        Contact& contact = contacts_.emplace_back();
        write_sphere_plane(centre, sphere.radius, plane.point, plane.normal, contact);
        // The sphere is body 1, so that the normal points from the plane to it.
        contact.body1 = sphere.index;
        contact.body2 = plane.index;
        return;
    }
    add_contact_if_any(i, j);
}

void World::respond() {
    proxies_fresh_ = false;
    if (!(respond_contacts() == 0.0)) guard("respond");
}

double World::respond_contacts() {
    response_energy_change_ = 0.0;
    if (model_.respond == nullptr) return 0.0;
    // The guard's check of the two bodies rides along, while they are in cache.
    double sum = 0.0;
    const std::span<const Contact> contacts = unanswered_contacts();
    if (!shortcuts_.response_energy_probe) {
        for (const Contact& contact : contacts) {
            RigidBody& body1 = bodies_[contact.body1];
            RigidBody& body2 = bodies_[contact.body2];
            model_.respond(body1, body2, contact);
            sum += poison(body1) + poison(body2);
        }
        return sum;
    }
    for (const Contact& contact : contacts) {
        RigidBody& body1 = bodies_[contact.body1];
        RigidBody& body2 = bodies_[contact.body2];
        const double before = kinetic_energy(body1) + kinetic_energy(body2);
        model_.respond(body1, body2, contact);
        response_energy_change_ += kinetic_energy(body1) + kinetic_energy(body2) - before;
        sum += poison(body1) + poison(body2);
    }
    return sum;
}

void World::correct() {
    proxies_fresh_ = false;
    if (!(correct_contacts() == 0.0)) guard("correct");
}

void World::solve_contacts() {
    event_scratch_.copies_known = false;  // it may change any body
    solver_report_ = {};
    response_energy_change_ = 0.0;
    if (model_.contact_solver == nullptr) return;
    const bool probe = shortcuts_.response_energy_probe;
    double before = 0.0;
    if (probe)
        for (const RigidBody& body : bodies_) before += kinetic_energy(body);
    const ContactSolverSettings& solver = settings_.contact_solver;
    contact_solver_.reserve(contacts_.capacity());
    std::span<const Contact> solved = contacts_;
    if (solver.sleeping) {
        // Sized with the contacts, in the steps where they grow: a warm step allocates nothing.
        if (awake_contacts_.capacity() < contacts_.capacity()) awake_contacts_.reserve(contacts_.capacity());
        if (asleep_contacts_.capacity() < contacts_.capacity()) asleep_contacts_.reserve(contacts_.capacity());
        asleep_contacts_.clear();
        sleeping_.wake_touched(bodies_, contacts_);
        if (sleeping_.sleeping() > 0) {
            // A sleeping island's contacts are left out (an awake body's contact with a
            // sleeping one woke it above); those with the ground or a wall of a sleeping body too.
            awake_contacts_.clear();
            for (const Contact& contact : contacts_) {
                const RigidBody& body1 = bodies_[contact.body1];
                const RigidBody& body2 = bodies_[contact.body2];
                if ((!body1.is_immovable() && !sleeping_.asleep(contact.body1)) ||
                    (!body2.is_immovable() && !sleeping_.asleep(contact.body2)))
                    awake_contacts_.push_back(contact);
                else
                    asleep_contacts_.push_back(contact);
            }
            solved = awake_contacts_;
        }
    }
    solver_report_ = contact_solver_.solve(bodies_, solved, *model_.contact_solver, solver, settings_.position_correction,
                                           settings_.time_step, -settings_.gravity, settings_.gravity,
                                           gravity_position_factor(settings_.integrator),
                                           solver.sleeping ? sleeping_.woken() : std::span<const std::uint8_t>{});
    contact_solver_.keep_for_waking(asleep_contacts_);
    if (solver.sleeping) sleeping_.fall_asleep(bodies_, solver, settings_.time_step);
    double after = 0.0;
    double sum = 0.0;
    for (const RigidBody& body : bodies_) {
        if (probe) after += kinetic_energy(body);
        sum += poison(body);
    }
    response_energy_change_ = after - before;
    if (!(sum == 0.0)) guard("solve contacts");
}

double World::correct_contacts() {
    if (model_.correct == nullptr) return 0.0;
    double sum = 0.0;
    for (const Contact& contact : unanswered_contacts()) {
        RigidBody& body1 = bodies_[contact.body1];
        RigidBody& body2 = bodies_[contact.body2];
        model_.correct(body1, body2, contact, settings_.position_correction);
        sum += poison(body1) + poison(body2);
    }
    return sum;
}

Probes World::probes() const {
    Probes p = measure(bodies_, settings_.gravity, shortcuts_.skip_still_rotation);
    p.time = time_;
    p.response_energy_change = response_energy_change_;
    p.contacts = static_cast<int>(contacts_.size());
    for (const Contact& contact : contacts_) p.penetration_max = std::max(p.penetration_max, contact.penetration);
    return p;
}

}  // namespace workbook

namespace workbook {

std::vector<StageUse> World::plan() const {
    std::size_t movable = 0, spinning = 0, planes = 0, movable_spheres = 0;
    double smallest_radius = std::numeric_limits<double>::infinity();
    for (const RigidBody& body : bodies_) {
        if (body.shape.kind == ShapeKind::sphere) smallest_radius = std::min(smallest_radius, body.shape.radius);
        if (body.is_immovable()) {
            planes += body.shape.kind == ShapeKind::plane ? 1 : 0;
            continue;
        }
        ++movable;
        movable_spheres += body.shape.kind == ShapeKind::sphere ? 1 : 0;
        if (body.angular_velocity != Vector3{}) ++spinning;
    }
    const std::size_t immovable = bodies_.size() - movable;
    const auto n = std::to_string(bodies_.size());
    std::vector<StageUse> stages;
    stages.push_back({"integrate: positions", true, std::to_string(movable) + " movable bodies"});
    const bool gravity = has_gravity(settings_, shortcuts_);
    stages.push_back({"integrate: gravity", gravity, gravity ? "gravity is not zero" : "gravity is zero"});
    const bool rotation = !shortcuts_.skip_still_rotation || spinning > 0;
    stages.push_back({"integrate: rotation", rotation,
                      rotation ? std::to_string(spinning) + " bodies spin at the start; the others are skipped while they do not"
                               : "no body spins at the start; skipped for each body as long as it does not"});
    const bool grid = shortcuts_.broad_phase && bodies_.size() >= shortcuts_.broad_phase_from;
    stages.push_back({"detect: broad phase (grid)", grid,
                      grid ? n + " bodies; " + std::to_string(planes) + " planes are paired only with bodies that reach them"
                           : n + " bodies, fewer than " + std::to_string(shortcuts_.broad_phase_from) +
                                 ": testing every pair is cheaper"});
    const std::size_t immovable_pairs = immovable > 1 ? immovable * (immovable - 1) / 2 : 0;
    stages.push_back({"detect: pairs of immovable bodies", !shortcuts_.skip_immovable_pairs,
                      std::to_string(immovable_pairs) + " such pairs, never tested"});
    const bool discrete = settings_.contact_timing == ContactTiming::discrete;
    const bool swept = discrete && settings_.swept_spheres && movable_spheres > 0;
    std::string why = "no movable sphere";
    if (!discrete) why = "event timing answers each contact at its moment";
    else if (!settings_.swept_spheres) why = "off in this scene (swept_spheres)";
    else if (swept) {
        char radius[32];
        std::snprintf(radius, sizeof radius, "%.3g", smallest_radius);
        why = std::to_string(movable_spheres) + " movable spheres; each traced in a step where it moves further than " +
              radius + " m (the smallest radius), against the candidates " + (grid ? "the grid finds" : "of every body");
    }
    stages.push_back({"detect: swept test", swept, why});
    if (model_.contact_solver != nullptr) {
        const ContactSolverSettings& solver = settings_.contact_solver;
        char still[32];
        std::snprintf(still, sizeof still, "%g", solver.sleep_time);
        const std::string sleeping = solver.sleeping ? std::string("; islands still for ") + still +
                                                           " s sleep until touched, and a step with every body asleep detects and solves nothing"
                                                     : std::string("; sleeping off");
        const std::string passes =
            solver.substeps > 0 ? "in " + std::to_string(solver.substeps) + " substeps of soft contacts (a push and " +
                                      std::to_string(solver.relax_passes) +
                                      (solver.relax_passes == 1 ? " relax pass each)" : " relax passes each)")
                                : "up to " + std::to_string(solver.velocity_iterations) + " velocity and " +
                                      std::to_string(solver.position_iterations) + " position passes";
        std::string speculative;
        if (solver.speculative_distance > 0.0) {
            char distance[32];
            std::snprintf(distance, sizeof distance, "%g", solver.speculative_distance);
            speculative = std::string("; speculative contacts for bodies apart by less than ") + distance + " m";
        }
        const std::string sweeps =
            solver.substeps > 0 || solver.shock_sweeps == 0
                ? std::string()
                : ", " + std::to_string(solver.shock_sweeps) + (solver.shock_sweeps == 1 ? " shock sweep" : " shock sweeps") +
                  " after the velocity passes";
        stages.push_back({"solve contacts", true,
                          "responder '" + std::string(model_.name) + "': all contacts together, " + passes + sweeps +
                              (solver.warm_start ? ", warm started" : ", not warm started") + sleeping + speculative});
        return stages;
    }
    stages.push_back({"respond", model_.respond != nullptr,
                      model_.respond != nullptr ? "responder '" + std::string(model_.name) + "'" : "the model has no velocity responder"});
    stages.push_back({"respond: energy probe", model_.respond != nullptr && shortcuts_.response_energy_probe,
                      shortcuts_.response_energy_probe ? "recorded (response_energy_change)" : "not recorded by this run"});
    stages.push_back({"correct", model_.correct != nullptr,
                      model_.correct != nullptr ? "position corrector of '" + std::string(model_.name) + "'"
                                                : "the model has no position corrector"});
    return stages;
}

}  // namespace workbook
