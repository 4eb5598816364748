#include "workbook/swept_spheres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "workbook/box_detection.hpp"
#include "workbook/broad_phase.hpp"
#include "workbook/detection.hpp"
#include "workbook/shape_pairs.hpp"

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

/// The unit vector from `from` towards `to` (a contact normal, pointing at body 1), or the
/// fixed normal detection uses when the two points coincide.
Vector3 away_from(const Vector3& from, const Vector3& to) {
    const Vector3 offset = to - from;
    const double distance = length(offset);
    return distance > 0.0 ? offset / distance : coincident_centres_normal;
}

/// away_from(now, to), unless `now` is no distance from `to`: then away_from(then, to).
Vector3 normal_now_or_then(const Vector3& now, const Vector3& then, const Vector3& to) {
    return length(to - now) > 0.0 ? away_from(now, to) : away_from(then, to);
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

namespace {

/// One run of the swept test over the bodies of a detect() (see swept_spheres.hpp), in three
/// parts a newcomer can read one at a time: find each fast sphere's earliest touch
/// (earliest_touch()), move it back there (move_back()), then detect the moved spheres again
/// (detect_moved_again()).
class Sweep {
public:
    Sweep(std::span<RigidBody> bodies, const SweepGrid& grid, std::vector<Contact>& contacts, SweepScratch& scratch)
        : bodies_(bodies), grid_(grid), use_grid_(grid.broad_phase != nullptr), contacts_(contacts), scratch_(scratch),
          count_(static_cast<std::uint32_t>(bodies.size())) {}

    void run(double dt, const Vector3& gravity_term) {
        if (!use_grid_) gather_starts(dt, gravity_term);
        clear_scratch();
        for (std::uint32_t i = 0; i < count_; ++i) {
            Vector3 fast_start;
            const EarliestTouch touch = earliest_touch(i, fast_start);
            if (touch.partner != count_) scratch_.found.push_back(move_back(i, fast_start, touch));
        }
        if (scratch_.moved.empty()) return;
        detect_moved_again();
        for (std::uint32_t i : scratch_.moved) scratch_.is_moved[i] = 0;
    }

private:
    /// Without the grid: each body's start (the grid's gathering found them already), kept
    /// while bodies are moved back, as a body moved back did start there; and the smallest
    /// sphere radius, the travel from which a sphere is traced.
    void gather_starts(double dt, const Vector3& gravity_term) {
        scratch_.starts.resize(count_);
        for (std::uint32_t j = 0; j < count_; ++j) scratch_.starts[j] = start_of_step(bodies_[j], dt, gravity_term);
        smallest_radius_ = std::numeric_limits<double>::infinity();
        for (const RigidBody& body : bodies_)
            if (body.shape.kind == ShapeKind::sphere) smallest_radius_ = std::min(smallest_radius_, body.shape.radius);
    }

    /// Bodies moved back, flagged by index, and the touching contacts found on the way, in the
    /// order they were found; both are merged into the contacts at the end (detect_moved_again()).
    void clear_scratch() {
        scratch_.moved.clear();
        scratch_.found.clear();
        if (scratch_.is_moved.size() < count_) {
            scratch_.is_moved.resize(count_, 0);
            // Room for more moves than a step makes (the gas of bench/ moves 0.7% of its spheres a
            // step), so that a warm step does not allocate when one happens to make a few more.
            scratch_.moved.reserve(count_ / 32 + 16);
            scratch_.found.reserve(count_ / 32 + 16);
            scratch_.candidates.reserve(256);
        }
    }

    /// Where body i started the step.
    [[nodiscard]] const Vector3& start_of(std::uint32_t i) const {
        return use_grid_ ? grid_.proxies->proxies[i].start : scratch_.starts[i];
    }

    /// Body i's earliest touch along its path (none unless it is a fast sphere), and its start.
    EarliestTouch earliest_touch(std::uint32_t i, Vector3& fast_start) const {
        EarliestTouch touch{1.0, count_};
        if (use_grid_) {
            touch_grid_partners(i, touch, fast_start);
            return touch;
        }
        // Without the grid, every body is tried.
        fast_start = scratch_.starts[i];
        const RigidBody& body = bodies_[i];
        if (body.is_immovable() || body.shape.kind != ShapeKind::sphere) return touch;
        if (!(length(body.position - fast_start) > smallest_radius_)) return touch;
        for (std::uint32_t j = 0; j < count_; ++j)
            if (j != i) touch.offer(first_touch(body, fast_start, bodies_[j], scratch_.starts[j]), j);
        return touch;
    }

    /// With this step's grid, only the partners the broad phase found are tried (the same
    /// answer as trying all: BroadPhase::sweep_partners()); only fast spheres have any. Most
    /// partners could not touch as the grid saw them and are tried again only if they have been
    /// moved back since: the sphere itself is read only when one can. Ends come from the
    /// proxies: the same numbers as the bodies' positions (a body moved back has its proxy moved
    /// with it), read from contiguous memory.
    void touch_grid_partners(std::uint32_t i, EarliestTouch& touch, Vector3& fast_start) const {
        const ProxySet& set = *grid_.proxies;
        const GridProxy* p = nullptr;
        Vector3 end;
        for (const std::uint32_t entry : grid_.broad_phase->sweep_partners(i)) {
            const std::uint32_t j = entry & BroadPhase::partner_index;
            const bool moved = scratch_.is_moved[j] != 0;
            if (!(entry & BroadPhase::partner_may_touch) && !moved) continue;
            if (p == nullptr) {
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
            if (!q.sphere) {
                touch.offer(first_touch_box(end, fast_start, p->radius, bodies_[j], other_end, q.start), j);
                continue;
            }
            if (!moved || spheres_may_touch(end, fast_start, p->radius, other_end, q.start, q.radius))
                touch.offer(first_touch_spheres(end, fast_start, p->radius, other_end, q.start, q.radius), j);
        }
    }

    /// The fast sphere i goes back to the moment of touching, and the contacts found for it at
    /// the end of the step give way to the one found on the way (returned). Its partner keeps
    /// its place and its other contacts (taking those away would let a resting body sink).
    Contact move_back(std::uint32_t i, const Vector3& fast_start, const EarliestTouch& touch) {
        RigidBody& fast = bodies_[i];
        const double earliest = touch.fraction;
        const RigidBody& other = bodies_[touch.partner];
        const Vector3 other_start = start_of(touch.partner);
        fast.position = fast_start + (fast.position - fast_start) * earliest;
        if (use_grid_) {
            GridProxy& p = grid_.proxies->proxies[i];
            p.x = fast.position.x, p.y = fast.position.y, p.z = fast.position.z;
        }
        const Vector3 other_then = other_start + (other.position - other_start) * earliest;
        scratch_.moved.push_back(i);
        scratch_.is_moved[i] = 1;
        Contact contact;
        contact.body1 = i;
        contact.body2 = touch.partner;
        // The normal and the point are those of the two bodies where the step leaves them (the
        // fast sphere moved back, the partner at its end), as detection would write them: the
        // responders take lever arms from the bodies' centres as they stand. Taken where the
        // partner was at the moment of touching, a partner that moved on since got a lever arm
        // across the normal, and the impulse of a frictionless ball spun it (up to 21 rad/s in
        // a pile). Only when the partner's centre is where the fast sphere's is does the normal
        // come from the moment of touching.
        switch (pair_of(fast.shape.kind, other.shape.kind)) {
            case ShapePair::sphere_plane: contact.normal = rotate(other.orientation, other.shape.normal); break;
            case ShapePair::sphere_box:
                contact.normal = normal_now_or_then(nearest_point_on_box(other, other.position, fast.position),
                                                    nearest_point_on_box(other, other_then, fast.position), fast.position);
                break;
            case ShapePair::sphere_sphere: contact.normal = normal_now_or_then(other.position, other_then, fast.position); break;
            case ShapePair::plane_plane:
            case ShapePair::plane_box:
            case ShapePair::box_box: break;  // the fast body is a sphere
        }
        contact.add_point(fast.position - contact.normal * fast.shape.radius, 0.0);
        return contact;  // the pair was not among the contacts: it did not overlap at the end
    }

    /// The contacts found for a moved sphere at the end of the step no longer hold; it is
    /// detected again where it now is. In a dense pile that place overlaps other bodies, and
    /// often the partner itself, which has moved on since the moment of touching; leaving those
    /// overlaps out of this step's correction let them grow (to two thirds of a diameter under
    /// 100 g in the stress corpus), and the projection of such overlaps then pushed neighbours'
    /// centres through the walls of a box. Only when the partner does not overlap it there does
    /// the pair get the touching contact of the moment they met.
    ///
    /// One pass, as if each move (in index order) had at once removed every contact of the moved
    /// sphere, detected it again against every body where they stood then, and appended its
    /// touching contact: a detected contact stays unless one of its bodies moved; a contact
    /// found for moved sphere i stays unless its other body moved later (at a larger index),
    /// which is then detected again against i in its turn.
    void detect_moved_again() {
        std::erase_if(contacts_, [&](const Contact& c) { return scratch_.is_moved[c.body1] || scratch_.is_moved[c.body2]; });
        if (use_grid_) gather_boxes();
        for (std::size_t k = 0; k < scratch_.moved.size(); ++k) {
            const std::uint32_t i = scratch_.moved[k];
            const Contact& touching = scratch_.found[k];
            bool partner_overlaps = false;
            for (const std::uint32_t j : candidates_again(i)) {
                if (j == i || (scratch_.is_moved[j] && j > i)) continue;
                auto contact = i < j ? collide(bodies_[i], i, bodies_[j], j) : collide(bodies_[j], j, bodies_[i], i);
                if (!contact) continue;
                contacts_.push_back(*contact);
                partner_overlaps = partner_overlaps || j == touching.body2;
            }
            if (!partner_overlaps && !(touching.body2 > i && scratch_.is_moved[touching.body2])) contacts_.push_back(touching);
        }
    }

    /// The boxes, which the swept test's partners leave out.
    void gather_boxes() {
        scratch_.boxes.clear();
        const ProxySet& set = *grid_.proxies;
        for (std::uint32_t j = 0; j < count_; ++j)
            if (!set.proxies[j].sphere && !set.proxies[j].plane) scratch_.boxes.push_back(j);
    }

    /// The bodies moved sphere i is detected again against, in index order. With the grid, the
    /// spheres that may overlap it where it now is are among its swept partners (its place is on
    /// its path, theirs on theirs); the planes and the boxes are tried whole (planes are
    /// partners only when a centre ended behind them). Without it, every body.
    std::span<const std::uint32_t> candidates_again(std::uint32_t i) {
        std::vector<std::uint32_t>& candidates = scratch_.candidates;
        if (!use_grid_) {
            candidates.resize(count_);
            for (std::uint32_t j = 0; j < count_; ++j) candidates[j] = j;
            return candidates;
        }
        candidates.assign(scratch_.boxes.begin(), scratch_.boxes.end());
        for (const PlaneProxy& plane : grid_.proxies->planes) candidates.push_back(plane.index);
        for (const std::uint32_t entry : grid_.broad_phase->sweep_partners(i)) candidates.push_back(entry & BroadPhase::partner_index);
        // (The iterator algorithms, not std::ranges: Clang 14 cannot compile ranges::unique
        // with GCC 12's standard library, and libc++ 14 has none of the ranges algorithms.)
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        return candidates;
    }

    std::span<RigidBody> bodies_;
    SweepGrid grid_;
    bool use_grid_;
    std::vector<Contact>& contacts_;
    SweepScratch& scratch_;
    std::uint32_t count_;
    double smallest_radius_ = 0.0;  ///< without the grid: the travel from which a sphere is traced
};

}  // namespace

void sweep_fast_spheres(std::span<RigidBody> bodies, double dt, const Vector3& gravity_term, const SweepGrid& grid,
                        std::vector<Contact>& contacts, SweepScratch& scratch) {
    Sweep(bodies, grid, contacts, scratch).run(dt, gravity_term);
}

}  // namespace workbook
