#include "workbook/swept_spheres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "workbook/box_detection.hpp"
#include "workbook/detection.hpp"
#include "workbook/event_timing.hpp"
#include "workbook/shape_pairs.hpp"
#include "workbook/world.hpp"

namespace workbook {

namespace {

/// The fraction s in [0, 1) of the straight paths at which sphere a (start a0, end a1, radius
/// ra) first touches plane (point, unit normal), or nothing: only a centre that ended behind
/// the plane has tunnelled.
std::optional<double> first_touch_plane(const Vector3& a1, const Vector3& a0, double ra, const Vector3& point,
                                        const Vector3& normal) {
    const double h0 = dot(a0 - point, normal) - ra;
    const double h1 = dot(a1 - point, normal) - ra;
    // A shallower overlap is an ordinary contact that detection has already found. A sphere
    // already touching at the start is stopped where it started.
    if (h0 + ra < 0.0 || h1 + ra >= 0.0) return std::nullopt;
    return h0 <= 0.0 ? 0.0 : h0 / (h0 - h1);
}

/// The same for two spheres (starts a0, b0, ends a1, b1); pairs that overlapped at the start
/// are not swept.
std::optional<double> first_touch_spheres(const Vector3& a1, const Vector3& a0, double ra, const Vector3& b1,
                                          const Vector3& b0, double rb) {
    const Vector3 d = a0 - b0;
    const Vector3 u = (a1 - a0) - (b1 - b0);
    const double radii = ra + rb;
    const double distance = length(d);
    const double gap = distance - radii;
    const double approach = dot(d, u);
    if (gap < 0.0 || approach >= 0.0) return std::nullopt;
    // A pair that overlaps at the end of the step was found by detection; only a pair that went
    // through each other and out again is tunnelling.
    if (length(a1 - b1) < radii) return std::nullopt;
    const double uu = length_squared(u);
    const double c = gap * (distance + radii);
    const double discriminant = approach * approach - uu * c;
    if (discriminant < 0.0) return std::nullopt;
    const double s = c / (-approach + std::sqrt(discriminant));  // the smaller root, without cancellation
    return s < 1.0 ? std::optional<double>(s) : std::nullopt;
}

/// The same for a sphere (start a0, end a1, radius ra) and a box (start b0, end b1, turned as
/// it is at the end). The sphere's centre moves along a straight line relative to the box, and
/// its distance from a convex body along a line is a convex function of s: its least value is
/// found by golden-section search, and the first touch before it by bisection, both to
/// rounding. As for two spheres, only a pair apart at both ends that came within touching
/// distance on the way has tunnelled.
std::optional<double> first_touch_box(const Vector3& a1, const Vector3& a0, double ra, const RigidBody& box,
                                      const Vector3& b1, const Vector3& b0) {
    const Vector3 d = a0 - b0;
    const Vector3 u = (a1 - a0) - (b1 - b0);
    // The distance from the box at fraction s of the path, with the box held at its end position.
    const auto distance = [&](double s) {
        const Vector3 centre = b1 + d + u * s;
        return length(centre - nearest_point_on_box(box, b1, centre));
    };
    if (!(distance(0.0) >= ra) || !(distance(1.0) >= ra)) return std::nullopt;
    constexpr double golden = 0.6180339887498949;
    double lo = 0.0, hi = 1.0;
    for (int n = 0; n < 200 && hi - lo > 1e-15; ++n) {
        const double m1 = hi - golden * (hi - lo), m2 = lo + golden * (hi - lo);
        if (distance(m1) < distance(m2)) hi = m2;
        else lo = m1;
    }
    const double nearest = 0.5 * (lo + hi);
    if (!(distance(nearest) < ra)) return std::nullopt;
    // distance(0) >= ra > distance(nearest): the first touch lies between.
    lo = 0.0;
    hi = nearest;
    for (int n = 0; n < 200; ++n) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (distance(mid) < ra ? hi : lo) = mid;
    }
    return lo;
}

/// The touch of fast sphere `a` (start a0) with body `b` (start b0), or nothing.
std::optional<double> first_touch(const RigidBody& a, const Vector3& a0, const RigidBody& b, const Vector3& b0) {
    // `a` is a sphere: only the sphere's pairs can come up (shape_pairs.hpp).
    switch (pair_of(a.shape.kind, b.shape.kind)) {
        case ShapePair::sphere_sphere: return first_touch_spheres(a.position, a0, a.shape.radius, b.position, b0, b.shape.radius);
        case ShapePair::sphere_box: return first_touch_box(a.position, a0, a.shape.radius, b, b.position, b0);
        case ShapePair::sphere_plane:
            return first_touch_plane(a.position, a0, a.shape.radius, b.position, rotate(b.orientation, b.shape.normal));
        case ShapePair::plane_plane:
        case ShapePair::plane_box:
        case ShapePair::box_box: return std::nullopt;  // boxes and planes are not traced
    }
    return std::nullopt;
}

/// The earliest touch of fast sphere i, and among equally early ones the partner of smallest
/// index: what trying every body in index order finds, whatever order the candidates come in.
struct EarliestTouch {
    double fraction = 1.0;
    std::uint32_t partner;
    void offer(std::optional<double> s, std::uint32_t j) {
        if (s && (*s < fraction || (*s == fraction && fraction < 1.0 && j < partner))) {
            fraction = *s;
            partner = j;
        }
    }
};

}  // namespace

void World::sweep_fast_spheres() {
    World& world = *this;
    std::span<RigidBody> bodies = world.bodies_;
    SweepScratch& scratch = world.sweep_scratch_;
    const auto count = static_cast<std::uint32_t>(bodies.size());
    const WorldSettings& settings = world.settings_;
    // With this step's grid, only the partners the broad phase found are tried (same answer as
    // trying all: BroadPhase::sweep_partners()); without it, every body.
    ProxySet& set = world.proxies_;
    const bool use_grid = world.used_broad_phase_ && world.broad_phase_.has_grid() && set.swept;

    // Each body's start, kept while bodies are moved back: a body moved back did start there.
    // The grid's gathering found them already.
    std::vector<Vector3>& starts = scratch.starts;
    if (!use_grid) {
        const double dt = settings.time_step;
        const Vector3 gravity_term = settings.gravity * ((1.0 - gravity_position_factor(settings.integrator)) * dt * dt);
        starts.resize(count);
        for (std::uint32_t j = 0; j < count; ++j) starts[j] = start_of_step(bodies[j], dt, gravity_term);
    }
    double smallest_radius = std::numeric_limits<double>::infinity();
    if (!use_grid) {
        for (const RigidBody& body : bodies)
            if (body.shape.kind == ShapeKind::sphere) smallest_radius = std::min(smallest_radius, body.shape.radius);
    }

    // Bodies moved back, flagged by index, and the touching contacts found on the way, in the
    // order they were found; both are merged into the contacts at the end (see there).
    scratch.moved.clear();
    scratch.found.clear();
    if (scratch.is_moved.size() < count) {
        scratch.is_moved.resize(count, 0);
        // Room for more moves than a step makes (the gas of bench/ moves 0.7% of its spheres a
        // step), so that a warm step does not allocate when one happens to make a few more.
        scratch.moved.reserve(count / 32 + 16);
        scratch.found.reserve(count / 32 + 16);
        scratch.candidates.reserve(256);
    }

    for (std::uint32_t i = 0; i < count; ++i) {
        EarliestTouch touch{1.0, count};
        Vector3 fast_start;
        if (use_grid) {
            // Only fast spheres have partners (the grid found them). Most partners could not
            // touch as the grid saw them, and are tried again only if they have been moved back
            // since (see BroadPhase::sweep_partners()): the sphere itself is read only when one can.
            const std::span<const std::uint32_t> partners = world.broad_phase_.sweep_partners(i);
            const GridProxy* p = nullptr;
            Vector3 end;
            for (const std::uint32_t entry : partners) {
                const std::uint32_t j = entry & BroadPhase::partner_index;
                const bool moved = scratch.is_moved[j] != 0;
                if (!(entry & BroadPhase::partner_may_touch) && !moved) continue;
                if (p == nullptr) {
                    // Ends from the proxies: the same numbers as the bodies' positions (a body moved
                    // back has its proxy moved with it), read from contiguous memory.
                    p = &set.proxies[i];
                    end = {p->x, p->y, p->z};
                    fast_start = p->start;
                }
                const GridProxy& q = set.proxies[j];
                if (q.plane) {
                    const PlaneProxy& plane = *std::lower_bound(set.planes.begin(), set.planes.end(), j, plane_before);
                    touch.offer(first_touch_plane(end, fast_start, p->radius, plane.point, plane.normal), j);
                    continue;
                }
                const Vector3 other_end{q.x, q.y, q.z};
                const Vector3& other_start = q.start;
                if (!q.sphere) {
                    touch.offer(first_touch_box(end, fast_start, p->radius, bodies[j], other_end, other_start), j);
                    continue;
                }
                if (!moved || spheres_may_touch(end, fast_start, p->radius, other_end, other_start, q.radius))
                    touch.offer(first_touch_spheres(end, fast_start, p->radius, other_end, other_start, q.radius), j);
            }
        } else {
            fast_start = starts[i];
            const RigidBody& body = bodies[i];
            if (body.is_immovable() || body.shape.kind != ShapeKind::sphere) continue;
            if (!(length(body.position - fast_start) > smallest_radius)) continue;
            for (std::uint32_t j = 0; j < count; ++j)
                if (j != i) touch.offer(first_touch(body, fast_start, bodies[j], starts[j]), j);
        }
        if (touch.partner == count) continue;

        // The fast sphere goes back to the moment of touching, and the contacts found for it at
        // the end of the step give way to the one found on the way. Its partner keeps its place
        // and its other contacts (taking those away would let a resting body sink).
        RigidBody& fast = bodies[i];
        const double earliest = touch.fraction;
        const RigidBody& other = bodies[touch.partner];
        const Vector3 other_start = use_grid ? set.proxies[touch.partner].start : starts[touch.partner];
        fast.position = fast_start + (fast.position - fast_start) * earliest;
        if (use_grid) {
            GridProxy& p = set.proxies[i];
            p.x = fast.position.x, p.y = fast.position.y, p.z = fast.position.z;
        }
        const Vector3 other_then = other_start + (other.position - other_start) * earliest;
        scratch.moved.push_back(i);
        scratch.is_moved[i] = 1;
        Contact contact;
        const bool plane = other.shape.kind == ShapeKind::plane;
        contact.body1 = i;
        contact.body2 = touch.partner;
        // The normal and the point are those of the two bodies where the step leaves them (the
        // fast sphere moved back, the partner at its end), as detection would write them: the
        // responders take lever arms from the bodies' centres as they stand. Taken where the
        // partner was at the moment of touching, a partner that moved on since got a lever arm
        // across the normal, and the impulse of a frictionless ball spun it (up to 21 rad/s in
        // a pile). Only when the partner's centre is where the fast sphere's is does the
        // normal come from the moment of touching.
        if (plane) {
            contact.normal = rotate(other.orientation, other.shape.normal);
        } else {
            const bool box = other.shape.kind == ShapeKind::box;
            const Vector3 offset = fast.position - (box ? nearest_point_on_box(other, other.position, fast.position) : other.position);
            const Vector3 then = fast.position - (box ? nearest_point_on_box(other, other_then, fast.position) : other_then);
            const double distance = length(offset), distance_then = length(then);
            contact.normal = distance > 0.0        ? offset / distance
                             : distance_then > 0.0 ? then / distance_then
                                                   : coincident_centres_normal;
        }
        contact.add_point(fast.position - contact.normal * fast.shape.radius, 0.0);
        scratch.found.push_back(contact);  // the pair was not among the contacts: it did not overlap at the end
    }
    if (scratch.moved.empty()) return;

    // The contacts found for a moved sphere at the end of the step no longer hold; it is
    // detected again where it now is. In a dense pile that place overlaps other bodies, and
    // often the partner itself, which has moved on since the moment of touching; leaving those
    // overlaps out of this step's correction let them grow (to two thirds of a diameter under
    // 100 g in the stress corpus), and the projection of such overlaps then pushed neighbours'
    // centres through the walls of a box. Only when the partner does not overlap it there does
    // the pair get the touching contact of the moment they met.
    //
    // One pass, as if each move (in index order) had at once removed every contact of the moved
    // sphere, detected it again against every body where they stood then, and appended its
    // touching contact: a detected contact stays unless one of its bodies moved; a contact
    // found for moved sphere i stays unless its other body moved later (at a larger index),
    // which is then detected again against i in its turn.
    std::erase_if(world.contacts_, [&](const Contact& c) { return scratch.is_moved[c.body1] || scratch.is_moved[c.body2]; });
    // With the grid, the spheres that may overlap sphere i where it now is are among its swept
    // partners (its place is on its path, theirs on theirs); the planes and the boxes are tried
    // whole. Sorted, the candidates are tried in the same order as every body would be.
    scratch.boxes.clear();
    if (use_grid)
        for (std::uint32_t j = 0; j < count; ++j)
            if (!set.proxies[j].sphere && !set.proxies[j].plane) scratch.boxes.push_back(j);
    for (std::size_t k = 0; k < scratch.moved.size(); ++k) {
        const std::uint32_t i = scratch.moved[k];
        const Contact& touching = scratch.found[k];
        bool partner_overlaps = false;
        auto try_body = [&](std::uint32_t j) {
            if (j == i || (scratch.is_moved[j] && j > i)) return;
            auto contact = i < j ? collide(bodies[i], i, bodies[j], j) : collide(bodies[j], j, bodies[i], i);
            if (!contact) return;
            world.contacts_.push_back(*contact);
            partner_overlaps = partner_overlaps || j == touching.body2;
        };
        if (use_grid) {
            // Planes are partners only when a centre ended behind them, so every plane is tried.
            scratch.candidates.assign(scratch.boxes.begin(), scratch.boxes.end());
            for (const PlaneProxy& plane : set.planes) scratch.candidates.push_back(plane.index);
            for (const std::uint32_t entry : world.broad_phase_.sweep_partners(i))
                scratch.candidates.push_back(entry & BroadPhase::partner_index);
            // (The iterator algorithms, not std::ranges: Clang 14 cannot compile ranges::unique
            // with GCC 12's standard library, and libc++ 14 has none of the ranges algorithms.)
            std::sort(scratch.candidates.begin(), scratch.candidates.end());
            scratch.candidates.erase(std::unique(scratch.candidates.begin(), scratch.candidates.end()),
                                     scratch.candidates.end());
            for (const std::uint32_t j : scratch.candidates) try_body(j);
        } else {
            for (std::uint32_t j = 0; j < count; ++j) try_body(j);
        }
        if (!partner_overlaps && !(touching.body2 > i && scratch.is_moved[touching.body2]))
            world.contacts_.push_back(touching);
    }
    for (std::uint32_t i : scratch.moved) scratch.is_moved[i] = 0;
}

}  // namespace workbook
