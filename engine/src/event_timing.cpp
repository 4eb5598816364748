#include "workbook/event_timing.hpp"
#include "workbook/tolerances.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "workbook/box_detection.hpp"
#include "workbook/detection.hpp"
#include "workbook/probes.hpp"
#include "workbook/rotation.hpp"
#include "workbook/shape_pairs.hpp"
#include "workbook/guards.hpp"
#include "workbook/response_model.hpp"
#include "workbook/world.hpp"  // Integrator

/// Asks the caches for the line holding `address`, to be read soon; nothing where the compiler
/// has no such hint (standard C++ has none, MSVC's differs). A hint only: no result depends on it.
#if defined(__GNUC__) || defined(__clang__)
#define WORKBOOK_PREFETCH(address) __builtin_prefetch(address)
#else
#define WORKBOOK_PREFETCH(address) static_cast<void>(address)
#endif

namespace workbook {
namespace {

/// Asks the caches for the `bytes` bytes from `from` on, every line of 64 bytes they touch.
inline void ask_caches_for(const void* from, std::size_t bytes) {
    const auto* first = static_cast<const char*>(from);
    for (std::size_t offset = 0; offset < bytes; offset += 64) WORKBOOK_PREFETCH(first + offset);
    WORKBOOK_PREFETCH(first + bytes - 1);
}

/// How many bodies ahead, in the order they go, the two passes over every body
/// (EventLoop::start() and finish()) ask the caches for the body they will read. At N =
/// 100,000 the bodies (328 bytes each) come from memory in both passes, and the processor's
/// own prefetching, which a stride of 328 bytes and several arrays read side by side leave
/// behind, kept them waiting: asked 16 bodies ahead, the pile's first pass's copies went from
/// about 3.1 to 2.6 ms a step and the pass to the end of the step from 2.7 to 2.0 ms (4 ahead
/// did half of that, 32 no more).
constexpr std::uint32_t pass_lookahead = 16;

/// What finish() reads and writes of a body: from its position to the end of its angular velocity.
constexpr std::size_t moved_bytes = offsetof(RigidBody, angular_velocity) + sizeof(Vector3) - offsetof(RigidBody, position);

/// Gaps within this share of the scene's length scale count as touching (tolerances.hpp).
constexpr double touching_tolerance = tolerances::touching;

/// The smallest root in (0, limit] of a t^2 + b t + c with c > 0 (the pair is apart now), or
/// nothing. The root is taken in the form that does not cancel.
std::optional<double> first_positive_root(double a, double b, double c, double limit) {
    if (a == 0.0) {
        if (b >= 0.0) return std::nullopt;
        const double t = -c / b;
        return t <= limit ? std::optional<double>(t) : std::nullopt;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return std::nullopt;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double best = std::numeric_limits<double>::infinity();
    for (double t : {q / a, q != 0.0 ? c / q : std::numeric_limits<double>::infinity()})
        if (t > 0.0 && t < best) best = t;
    return best <= limit ? std::optional<double>(best) : std::nullopt;
}

Vector3 acceleration_of(const RigidBody& body, const Vector3& gravity) {
    return body.is_immovable() ? Vector3{} : gravity;
}

/// How far a sphere, or a box that does not spin, reaches from its centre towards the plane of
/// unit normal `normal`: its radius, or the box's support sum_k h_k |a_k . n|.
double reach_towards(const RigidBody& body, const Vector3& normal) {
    if (body.shape.kind == ShapeKind::sphere) return body.shape.radius;
    const Matrix3 axes = to_matrix(body.orientation);
    const Vector3& h = body.shape.half_extents;
    return h.x * std::abs(axes(0, 0) * normal.x + axes(1, 0) * normal.y + axes(2, 0) * normal.z) +
           h.y * std::abs(axes(0, 1) * normal.x + axes(1, 1) * normal.y + axes(2, 1) * normal.z) +
           h.z * std::abs(axes(0, 2) * normal.x + axes(1, 2) * normal.y + axes(2, 2) * normal.z);
}

/// What the time of impact with a plane reads of the plane: the event loop hands it over from
/// its compact copies (EventBody and EventScratch::normals), time_of_impact() from the body.
struct PlaneMotion {
    Vector3 position;  ///< m, a point of the plane
    Vector3 velocity;  ///< m/s (a kinematic plane's; an immovable one has none)
    Vector3 normal;    ///< its unit normal in the world
};

/// A movable body whose lowest point towards a plane is `reach` below its centre, the centre at
/// `position` moving at `velocity`, against the plane: that point moves with the centre, along
/// the same parabola, so the gap is a quadratic in t.
std::optional<double> lowest_point_plane(const Vector3& position, const Vector3& velocity, double reach,
                                         const PlaneMotion& plane, const Vector3& gravity, double k, double limit) {
    const Vector3& normal = plane.normal;
    const double gap = dot(position - plane.position, normal) - reach;
    // A kinematic plane moves at its set velocity (an immovable one has none).
    const double rate = dot(velocity - plane.velocity, normal);
    const double curvature = k * dot(gravity, normal);  // gap(t) = gap + rate t + curvature t^2
    const double scale = std::abs(dot(position - plane.position, normal)) + reach;
    if (std::abs(gap) <= touching_tolerance * scale) {
        if (rate < 0.0) return 0.0;
        // Just bounced (or resting): the next touch is where the parabola comes back down.
        if (rate > 0.0 && curvature < 0.0) {
            const double t = -rate / curvature;
            return t <= limit ? std::optional<double>(t) : std::nullopt;
        }
        return std::nullopt;
    }
    if (gap < 0.0) return std::nullopt;
    // Over [0, limit] the gap is at least this; when it stays positive there is no root to look
    // for. Most steps of a falling or flying ball end here, without a square root or a division.
    if (gap + std::min(rate, 0.0) * limit + std::min(curvature, 0.0) * (limit * limit) > 0.0) return std::nullopt;
    return first_positive_root(curvature, rate, gap, limit);
}

/// A sphere, or a box that does not spin, against a plane (lowest_point_plane()).
std::optional<double> sphere_plane(const RigidBody& sphere, const RigidBody& plane, const Vector3& gravity, double k,
                                   double limit) {
    if (sphere.is_immovable()) return std::nullopt;
    const PlaneMotion seen{plane.position, plane.velocity, rotate(plane.orientation, plane.shape.normal)};
    return lowest_point_plane(sphere.position, sphere.velocity, reach_towards(sphere, seen.normal), seen, gravity, k, limit);
}

/// |d + u t + A t^2|^2 - R^2 for the quartic case.
double squared_gap(const Vector3& d, const Vector3& u, const Vector3& a, double radii, double t) {
    return length_squared(d + u * t + a * (t * t)) - radii * radii;
}

/// sphere_sphere()'s answer when the two do not meet within the limit. A double rather than
/// an empty std::optional: most of a pile's predictions end in sphere_sphere()'s first tests,
/// and an optional returned through memory cost them more than the tests themselves.
constexpr double no_impact = std::numeric_limits<double>::infinity();

/// What the time of impact of two spheres reads of each: the event loop hands it over from its
/// compact copies (EventBody), time_of_impact() from the bodies.
struct SphereMotion {
    Vector3 position;  ///< m
    Vector3 velocity;  ///< m/s
    double radius;     ///< m
    bool immovable;    ///< gravity does not move it
};

SphereMotion sphere_motion(const RigidBody& body) {
    return {body.position, body.velocity, body.shape.radius, body.is_immovable()};
}

Vector3 acceleration_of(const SphereMotion& sphere, const Vector3& gravity) {
    return sphere.immovable ? Vector3{} : gravity;
}

/// Two spheres relative to each other: the offset of the centres d, the relative velocity u,
/// and a, the relative acceleration times k, so that the offset is d + u tau + a tau^2 (the
/// file comment's motion); and the sum of the radii.
struct SpherePair {
    Vector3 d;      ///< m
    Vector3 u;      ///< m/s
    Vector3 a;      ///< m/s^2
    double radii;   ///< m
};

inline SpherePair relative_motion(const SphereMotion& s1, const SphereMotion& s2, const Vector3& gravity, double k) {
    return {s1.position - s2.position, s1.velocity - s2.velocity,
            (acceleration_of(s1, gravity) - acceleration_of(s2, gravity)) * k, s1.radius + s2.radius};
}

/// sphere_sphere()'s first tests, without a square root: true when they show that the pair
/// cannot touch within the limit. Most pairs of a step end here, so the event loop makes these
/// tests inline, where it has the two spheres at hand, and calls the rest only for the few
/// pairs that pass them (in a pile 1 in 15 predictions finds an impact).
inline bool cannot_meet_soon(const SpherePair& p, double limit) {
    // A pair that does not move relative to itself keeps its distance (a row of touching balls,
    // two balls falling together) ...
    if (p.u == Vector3{} && p.a == Vector3{}) return true;
    // ... two that share their acceleration (both falling, or both pinned) and are not closing
    // (d . u >= 0) only draw apart, |d + u t|^2 grows with t: every answer below would be
    // no_impact, touching or not. In a pile half the neighbours of a body that just bounced
    // are moving away from it ...
    if (!(p.a == Vector3{})) return false;
    const double approach = dot(p.d, p.u);
    if (approach >= 0.0) return true;
    // ... and two such that are closing stay at |d + u t|^2 >= |d|^2 + 2 t (d . u) >=
    // |d|^2 + 2 limit (d . u) over [0, limit]: when that is clear of the radii by more than
    // rounding (a relative conservative_slack, far wider than the touching band), they cannot
    // touch within the limit.
    const double nearest_squared = length_squared(p.d) + 2.0 * limit * approach;
    const double scale = length_squared(p.d) - 2.0 * limit * approach + p.radii * p.radii;
    return nearest_squared > p.radii * p.radii + tolerances::conservative_slack * scale;
}

/// The earliest tau in [0, limit] at which a pair of spheres that cannot_meet_soon() did not
/// rule out touches while approaching, or no_impact.
double first_touch(const SpherePair& p, double limit) {
    const Vector3& d = p.d;
    const Vector3& u = p.u;
    const Vector3& a = p.a;
    const double radii = p.radii;
    const double approach = dot(d, u);
    const double limit2 = limit * limit;
    // The centres close by at most reach = |u| limit + |a| limit^2 over [0, limit], where
    // reach^2 <= 2 (|u|^2 limit^2 + |a|^2 limit^4); centres more than 2 max(radii, reach) apart
    // cannot come within the radii.
    const double reach_squared = 2.0 * (length_squared(u) * limit2 + length_squared(a) * (limit2 * limit2));
    if (length_squared(d) > 4.0 * std::max(radii * radii, reach_squared)) return no_impact;
    const double distance = length(d);
    const double gap = distance - radii;
    if (std::abs(gap) <= touching_tolerance * (distance + radii)) {
        if (approach < 0.0) return 0.0;
        if (a == Vector3{}) return no_impact;
    } else if (gap < 0.0) {
        return no_impact;
    } else if (gap * gap > reach_squared) {
        return no_impact;  // the gap is wider than the reach
    }
    if (a == Vector3{}) {
        // |d + u t|^2 = R^2 with c = (|d| - R)(|d| + R) written so that it does not cancel.
        return first_positive_root(length_squared(u), 2.0 * approach, gap * (distance + radii), limit).value_or(no_impact);
    }
    // One body falls, the other is pinned: a quartic. Bracket the first sign change on a grid,
    // skipping the instant of touching itself, then bisect to rounding.
    constexpr int samples = 64;
    double previous_t = 0.0;
    double previous = std::max(squared_gap(d, u, a, radii, 0.0), 0.0);
    for (int i = 1; i <= samples; ++i) {
        const double t = limit * i / samples;
        const double value = squared_gap(d, u, a, radii, t);
        if (previous >= 0.0 && value < 0.0) {
            double lo = previous_t;
            double hi = t;
            for (int j = 0; j < 200 && lo < hi; ++j) {
                const double mid = 0.5 * (lo + hi);
                if (mid == lo || mid == hi) break;
                (squared_gap(d, u, a, radii, mid) < 0.0 ? hi : lo) = mid;
            }
            return lo;
        }
        previous_t = t;
        previous = value;
    }
    return no_impact;
}

/// The earliest tau in [0, limit] at which two spheres touch while approaching, or no_impact.
double sphere_sphere(const SphereMotion& s1, const SphereMotion& s2, const Vector3& gravity, double k, double limit) {
    const SpherePair p = relative_motion(s1, s2, gravity, k);
    return cannot_meet_soon(p, limit) ? no_impact : first_touch(p, limit);
}

/// Advances one body by tau along the motion of the file comment: a kinematic body at its set
/// velocity and spin, a movable one under gravity with free rotation (a box whose moments
/// differ precesses, Euler's equations, which turning it about a fixed w would miss).
void advance(RigidBody& body, const Vector3& gravity, double k, double tau) {
    if (tau <= 0.0) return;
    if (body.is_immovable()) {
        advance_kinematic(body, tau);
        return;
    }
    body.position += body.velocity * tau + gravity * (k * tau * tau);
    body.velocity += gravity * tau;
    if (body.angular_velocity != Vector3{}) advance_free_rotation(body, tau);
}

/// Shows `body` to time_of_impact() as it must see it `s` after the time its state refers to,
/// for as long as this lives: at its position then, with the velocity that makes
/// x + v tau + k g tau^2 continue the same curve (v + 2 k g s; the body's own velocity then is
/// v + g s, equal only for k = 1/2). A body is advanced in one piece from its state to its next
/// event, so predictions must follow that piece. The two vectors are changed in place and put
/// back afterwards: a copy of the whole body (328 bytes) at most predictions of a pile cost more
/// than the time of impact itself.
class SeenAfter {
public:
    SeenAfter(RigidBody& body, const Vector3& gravity, double k, double s)
        : body_(body), position_(body.position), velocity_(body.velocity) {
        if (s <= 0.0) return;
        if (body.is_immovable()) {
            body.position += velocity_ * s;
            return;
        }
        body.position += velocity_ * s + gravity * (k * s * s);
        body.velocity += gravity * (2.0 * k * s);
    }
    ~SeenAfter() {
        body_.position = position_;
        body_.velocity = velocity_;
    }
    SeenAfter(const SeenAfter&) = delete;
    SeenAfter& operator=(const SeenAfter&) = delete;

private:
    RigidBody& body_;
    Vector3 position_;
    Vector3 velocity_;
};

/// A sphere against a box that does not spin. The sphere's centre moves relative to the box
/// along d + u tau + a tau^2, and the gap is its distance from the box less the radius, which
/// has no closed form: it is sampled at steps of at most half the radius or the box's
/// thinnest half extent along that path (so that the sphere cannot cross the box between two
/// samples), and the first sample inside is bisected to rounding. A grazing touch shorter than
/// a sample step can be missed; the back-stop answers it if it still overlaps at the end.
std::optional<double> sphere_box(const RigidBody& sphere, const RigidBody& box, const Vector3& gravity, double k,
                                 double limit) {
    const Vector3 d = sphere.position - box.position;
    const Vector3 u = sphere.velocity - box.velocity;
    const Vector3 a = (acceleration_of(sphere, gravity) - acceleration_of(box, gravity)) * k;
    const double r = sphere.shape.radius;
    const auto gap = [&](double tau) {
        const Vector3 at = box.position + d + u * tau + a * (tau * tau);
        return length(at - nearest_point_on_box(box, box.position, at)) - r;
    };
    const double path = length(u) * limit + length(a) * limit * limit;
    const double start = gap(0.0);
    const Vector3& h = box.shape.half_extents;
    const double scale = length(d) + r + length(h);
    bool touching = std::abs(start) <= touching_tolerance * scale;
    if (touching) {
        const Vector3 nearest = nearest_point_on_box(box, box.position, sphere.position);
        if (dot(sphere.position - nearest, u) < 0.0) return 0.0;
    } else if (start < 0.0 || start > path) {
        return std::nullopt;  // overlapping already (the back-stop's), or too far to reach it
    }
    const double step = 0.5 * std::min({r, h.x, h.y, h.z});
    const double wanted = std::ceil(path / step);
    const int samples = static_cast<int>(std::clamp(wanted, 1.0, 4096.0));
    double previous_t = 0.0;
    for (int n = 1; n <= samples; ++n) {
        const double t = limit * n / samples;
        if (gap(t) < 0.0) {
            double lo = previous_t, hi = t;
            for (int j = 0; j < 200; ++j) {
                const double mid = 0.5 * (lo + hi);
                if (mid == lo || mid == hi) break;
                (gap(mid) < 0.0 ? hi : lo) = mid;
            }
            // Just bounced off (touching, moving away): a touch at the very start is not a new one.
            if (touching && lo == 0.0) return std::nullopt;
            return lo;
        }
        previous_t = t;
    }
    return std::nullopt;
}

/// The corners of a box touching a plane: those within rounding of the lowest (one, two for an
/// edge, four for a face), each a point of the contact.
void add_touching_corners(const RigidBody& box, const Vector3& plane_point, const Vector3& normal, Contact& contact) {
    const Matrix3 axes = to_matrix(box.orientation);
    const Vector3& h = box.shape.half_extents;
    std::array<Vector3, 8> corners;
    std::array<double, 8> heights;
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < 8; ++c) {
        const Vector3 local{(c & 1) != 0 ? h.x : -h.x, (c & 2) != 0 ? h.y : -h.y, (c & 4) != 0 ? h.z : -h.z};
        corners[c] = box.position + axes * local;
        heights[c] = dot(corners[c] - plane_point, normal);
        lowest = std::min(lowest, heights[c]);
    }
    const double scale = std::abs(dot(box.position - plane_point, normal)) + length(h);
    for (std::size_t c = 0; c < 8; ++c)
        if (heights[c] - lowest <= touching_tolerance * scale) contact.add_point(corners[c], 0.0);
}

/// The contact of a touching pair (no overlap), normal from body 2 to body 1.
Contact touching_contact(const RigidBody& b1, std::uint32_t i1, const RigidBody& b2, std::uint32_t i2) {
    Contact contact;
    contact.body1 = i1;
    contact.body2 = i2;
    // Body 1 is the sphere of a pair with one, the box of a box and a plane (answer_impact()).
    switch (pair_of(b1.shape.kind, b2.shape.kind)) {
        case ShapePair::sphere_box: {
            const Vector3 nearest = nearest_point_on_box(b2, b2.position, b1.position);
            const Vector3 offset = b1.position - nearest;
            const double distance = length(offset);
            contact.normal = distance > 0.0 ? offset / distance : coincident_centres_normal;
            contact.add_point(nearest, 0.0);
            break;
        }
        case ShapePair::plane_box:
            contact.normal = rotate(b2.orientation, b2.shape.normal);
            add_touching_corners(b1, b2.position, contact.normal, contact);
            break;
        case ShapePair::sphere_plane:
            contact.normal = rotate(b2.orientation, b2.shape.normal);
            contact.add_point(b1.position - contact.normal * b1.shape.radius, 0.0);
            break;
        case ShapePair::sphere_sphere: {
            const Vector3 offset = b1.position - b2.position;
            const double distance = length(offset);
            contact.normal = distance > 0.0 ? offset / distance : coincident_centres_normal;
            contact.add_point(b2.position + contact.normal * b2.shape.radius, 0.0);
            break;
        }
        case ShapePair::plane_plane:
        case ShapePair::box_box: break;  // never an impact (time_of_impact())
    }
    return contact;
}

/// Spheres, planes that do not turn, and boxes that do not spin (whose lowest point follows a
/// parabola) take part in the event loop; other bodies are left to the discrete back-stop.
bool takes_part(const RigidBody& body) {
    return body.shape.kind == ShapeKind::sphere ||
           (body.shape.kind == ShapeKind::plane && body.angular_velocity == Vector3{}) ||
           (body.shape.kind == ShapeKind::box && body.angular_velocity == Vector3{});
}

}  // namespace

double gravity_position_factor(Integrator integrator) {
    switch (integrator) {
        case Integrator::semi_implicit_euler: return 1.0;
        case Integrator::explicit_euler: return 0.0;
        case Integrator::exact_under_gravity: return 0.5;
    }
    return 0.5;
}

std::optional<double> time_of_impact(const RigidBody& a, const RigidBody& b, const Vector3& gravity, double k,
                                     double limit) {
    if (a.is_immovable() && b.is_immovable()) return std::nullopt;
    // A box that does not spin meets a plane like a sphere whose radius is the box's reach.
    const bool a_first = a.shape.kind == ShapeKind::sphere || (a.shape.kind == ShapeKind::box && b.shape.kind == ShapeKind::plane);
    const RigidBody& first = a_first ? a : b;   // the sphere, or the box against a plane
    const RigidBody& second = a_first ? b : a;
    switch (pair_of(a.shape.kind, b.shape.kind)) {
        case ShapePair::sphere_sphere: {
            const double tau = sphere_sphere(sphere_motion(a), sphere_motion(b), gravity, k, limit);
            return tau != no_impact ? std::optional<double>(tau) : std::nullopt;
        }
        case ShapePair::sphere_plane: return sphere_plane(first, second, gravity, k, limit);
        case ShapePair::sphere_box:
            return (second.angular_velocity == Vector3{}) ? sphere_box(first, second, gravity, k, limit) : std::nullopt;  // a box that does not spin
        case ShapePair::plane_box:
            return (first.angular_velocity == Vector3{}) ? sphere_plane(first, second, gravity, k, limit) : std::nullopt;
        case ShapePair::plane_plane:
        case ShapePair::box_box: return std::nullopt;  // never met / left to the back-stop
    }
    return std::nullopt;
}

namespace {

/// The heap's order: the earliest event on top, and among equally early ones the smallest
/// pair (i, then j), the one a scan of every pair in index order would pick. A type rather
/// than a function, so that the heap's every comparison is inlined, not called through a
/// pointer.
struct Later {
    bool operator()(const ImpactEvent& a, const ImpactEvent& b) const {
        if (a.t != b.t) return a.t > b.t;
        if (a.i != b.i) return a.i > b.i;
        return a.j > b.j;
    }
};

/// Later's order reversed, for sorting a slice's events earliest first. No time of impact is
/// a NaN (each is compared with its limit before it is given), but a NaN time would make the
/// order no strict weak order, and std::sort may then read past the range: one counts here
/// as later than any other time.
struct Earlier {
    bool operator()(const ImpactEvent& a, const ImpactEvent& b) const {
        constexpr double latest = std::numeric_limits<double>::infinity();
        const double ta = std::isnan(a.t) ? latest : a.t;
        const double tb = std::isnan(b.t) ? latest : b.t;
        if (ta != tb) return ta < tb;
        if (a.i != b.i) return a.i < b.i;
        return a.j < b.j;
    }
};

/// The event loop of one step over `bodies`; see move_impact_to_impact().
class EventLoop {
public:
    EventLoop(std::span<RigidBody> bodies, const EventMotion& motion, EventScratch& scratch)
        : bodies_(bodies), scratch_(scratch), gravity_(motion.gravity), k_(motion.k), dt_(motion.dt),
          gravity_reach_((std::abs(motion.k) + 1.0) * length(motion.gravity)),
          gravity_reach_along_(Vector3{std::abs(motion.gravity.x), std::abs(motion.gravity.y), std::abs(motion.gravity.z)} *
                               (std::abs(motion.k) + 1.0)),
          slice_count_(std::max<std::uint32_t>(1, static_cast<std::uint32_t>(bodies.size() / 8))),
          slices_per_second_(slice_count_ / motion.dt), count_(static_cast<std::uint32_t>(bodies.size())),
          boxes_(take_boxes(scratch)) {}

    /// Whether this step uses boxes (EventScratch::use_boxes), counting down the steps
    /// without them: after those, one step tries them again.
    static bool take_boxes(EventScratch& scratch) {
        if (scratch.use_boxes) return true;
        if (scratch.steps_without_boxes > 0 && --scratch.steps_without_boxes > 0) return false;
        scratch.use_boxes = true;
        return true;
    }

    /// Finds the candidate pairs of the step and their first impacts.
    void start() {
        EventScratch& s = scratch_;
        // The copies the last step left, unless the bodies may have changed since
        // (EventScratch::copies_known); not again until this step has ended.
        const bool known = s.copies_known && s.state.size() == count_ && s.roles.size() == count_;
        s.copies_known = false;
        if (known) note_after_last_step();
        s.state.resize(count_);
        s.roles.resize(count_);
        s.normals.resize(count_);
        s.events.assign(count_, 0);
        s.reach.resize(count_);
        s.extra.clear();
        s.extra_head.assign(count_, no_extra);
        s.extra_nodes.clear();
        // Room for one overlapping pair per body from the start, as the broad phase keeps for
        // its pairs, and for four times the last step's when that used half of it: a gas ends
        // most steps with none and a pile with about two per body, and growing only at a new
        // largest count would allocate now and then long after the scene warmed up.
        if (s.all_pairs.capacity() < count_) s.all_pairs.reserve(count_);
        if (s.all_pairs.capacity() < 2 * s.all_pairs.size()) s.all_pairs.reserve(4 * s.all_pairs.size());
        s.heap.clear();
        s.run.clear();
        s.run_next = 0;
        s.pending.clear();
        s.slice_head.assign(slice_count_, no_node);
        opened_ = 0;
        most_in_heap_ = 0;
        longest_run_ = 0;
        s.contacts.clear();
        s.moving_planes.clear();
        // Each body's bounding sphere widened by how far it can move this step at the velocity
        // it has: the pairs whose widened spheres overlap are the only ones that can meet. A
        // body that an impact sends further is searched again (outran()).
        s.proxies.clear(count_, true);  // compact copies: all the grid of widened spheres reads
        // Cells half as wide where they pay (ProxySet::fine_cells): the widened spheres of a pile
        // set cells that hold three bodies each, and a pair is found among fewer of them.
        s.proxies.fine_cells = true;
        for (std::uint32_t i = 0; i < count_; ++i) {
            // A body is read only where it has no copy from the last step (and planes, whose
            // normals the copies do not follow).
            const bool copied = known && !s.roles[i].plane;
            if (!known && i + pass_lookahead < count_) ask_caches_for(&bodies_[i + pass_lookahead], sizeof(RigidBody));
            if (!copied) note(i, 0.0);
            const EventBody& state = s.state[i];
            const EventRole& role = s.roles[i];
            s.reach[i].origin = state.position;
            s.reach[i].reach = can_move(i, dt_);
            if (boxes_) {
                s.reach[i].half_sides = box_half_sides(i, dt_);
                if (!role.plane) note_half_sides(s.reach[i].half_sides);
            }
            // As add() gathers a body (its bounding radius is the one note() took).
            if (copied) s.proxies.add_compact(state.position, state.bounding_radius + s.reach[i].reach, i, !role.immovable, role.sphere);
            else s.proxies.add(bodies_[i], i, 0.0, {}, s.reach[i].reach);
            if (role.plane && (bodies_[i].velocity != Vector3{} || bodies_[i].angular_velocity != Vector3{}))
                s.moving_planes.push_back(i);
        }
        s.broad_phase.find_pairs(s.proxies, s.pairs, false, false);  // in no particular order
        if (boxes_) leave_out_apart_pairs();
        // Each body's candidates, as lists by body.
        list_by_body(s.pairs, s.start, s.partners);
        // A kinematic plane that moves or turns can meet any body: each is its candidate. (Found
        // in the pass above: a pass of its own over the bodies cost a few percent at N = 100,000.)
        for (const std::uint32_t i : s.moving_planes)
            for (std::uint32_t j = 0; j < count_; ++j)
                if (j != i) add_candidate(j, i);
        // Pairs of spheres tested inline as changed() tests them (no body has had an event yet,
        // so none has reached max_events_per_body).
        for (const std::vector<BodyPair>* list : {&s.pairs, &s.extra}) {
            for (const BodyPair& p : *list) {
                const EventRole& a = s.roles[p.first];
                const EventRole& b = s.roles[p.second];
                if (!(a.sphere && b.sphere && a.takes_part && b.takes_part && !(a.immovable && b.immovable))) {
                    predict(p.first, p.second, 0.0);
                    continue;
                }
                const SpherePair pair = relative_motion(seen_at(p.first, 0.0), seen_at(p.second, 0.0), gravity_, k_);  // predict_spheres()
                if (!cannot_meet_soon(pair, dt_)) time_spheres(p.first, p.second, pair, 0.0);
            }
        }
    }

    /// The earliest pending event that still holds, or nothing. The sorted run and the heap
    /// hold the slices opened so far; every event of a later slice is later than all of them
    /// (slice_of() grows with the time), so the next slice is opened only when both are empty.
    /// The two give their events in the one order of Later (a total order of the events that
    /// can both hold), so the events come as they came from one heap.
    std::optional<ImpactEvent> next() {
        EventScratch& s = scratch_;
        for (;;) {
            while (s.run_next < s.run.size() || !s.heap.empty()) {
                ImpactEvent e;
                if (s.heap.empty() || (s.run_next < s.run.size() && Later{}(s.heap.front(), s.run[s.run_next]))) {
                    e = s.run[s.run_next++];
                } else {
                    std::pop_heap(s.heap.begin(), s.heap.end(), Later{});
                    e = s.heap.back();
                    s.heap.pop_back();
                }
                if (e.events_i == s.events[e.i] && e.events_j == s.events[e.j]) return e;
            }
            if (opened_ == slice_count_) return std::nullopt;
            open_slice();
        }
    }

    /// After the loop: room for at least twice what this step queued (four times when it
    /// grows), so that a warm step allocates nothing. How many events a step queues, and how
    /// many its slices hold at once, change from step to step (a slice holds a handful):
    /// growing only at a new largest count would allocate now and then long after the scene
    /// warmed up.
    void keep_room() {
        EventScratch& s = scratch_;
        if (s.pending.capacity() < 2 * s.pending.size()) s.pending.reserve(4 * s.pending.size());
        // The heap and the run with room for a few dozen events at least: in a gas most slices
        // hold one event or none, and the heap takes an event only when an impact is predicted
        // into the slice under way, which may first happen long after the scene warmed up.
        constexpr std::size_t least = 64;
        const std::size_t heap_room = std::max(least, most_in_heap_), run_room = std::max(least, longest_run_);
        if (s.heap.capacity() < 2 * heap_room) s.heap.reserve(4 * heap_room);
        if (s.run.capacity() < 2 * run_room) s.run.reserve(4 * run_room);
    }

    /// Advances body i to time t within the step, without noting it: its only caller,
    /// answer_impact(), changes the body again with the response and notes it after that (a
    /// note here as well was two copies of each body per event for nothing).
    void advance_to(std::uint32_t i, double t) { advance(bodies_[i], gravity_, k_, t - scratch_.state[i].since); }

    /// Copies into the compact arrays what predictions read of body i, whose state now refers
    /// to time t: after every change the loop makes to the body (a move, a response, which may
    /// also set a box spinning and so take it out of the loop).
    void note(std::uint32_t i, double t) {
        const RigidBody& body = bodies_[i];
        scratch_.state[i] = {body.position, body.velocity, t, bounding_radius(body)};
        scratch_.roles[i] = {takes_part(body), body.is_immovable(), body.shape.kind == ShapeKind::sphere,
                             body.shape.kind == ShapeKind::plane};
        if (body.shape.kind == ShapeKind::plane) scratch_.normals[i] = rotate(body.orientation, body.shape.normal);
    }

    /// At the start of a step whose copies the last one left (EventScratch::copies_known):
    /// notes again the bodies of its overlapping pairs, the only ones the discrete stages after
    /// it answered, and so may have changed.
    void note_after_last_step() {
        for (const BodyPair& p : scratch_.all_pairs) {
            note(p.first, 0.0);
            note(p.second, 0.0);
        }
    }

    /// After an event at time t: body i's impacts are predicted again with each candidate but
    /// `skip` (or with all, for no_body).
    void changed(std::uint32_t i, double t, std::uint32_t skip) {
        EventScratch& s = scratch_;
        ++s.events[i];
        if (outran(i, t)) search_again(i, t);
        const EventRole role = s.roles[i];
        if (s.events[i] >= max_events_per_body || !role.takes_part) return;
        // A sphere is seen at t once for all its candidates, and its pairs with spheres (most
        // of a pile's predictions) are tested here, inline: through predict() and a call for
        // every pair, the calls and the copies of the two spheres they passed cost about what
        // the tests themselves did.
        const SphereMotion seen = role.sphere ? seen_at(i, t) : SphereMotion{};
        const auto one = [&](std::uint32_t partner) {
            if (partner == skip) return;
            const EventRole& other = s.roles[partner];
            if (!(role.sphere && other.sphere)) {
                predict(i, partner, t);
                return;
            }
            if (!other.takes_part || (role.immovable && other.immovable) || s.events[partner] >= max_events_per_body) return;
            const SpherePair pair = relative_motion(seen, seen_at(partner, t), gravity_, k_);  // predict_spheres()
            if (!cannot_meet_soon(pair, dt_ - t)) time_spheres(i, partner, pair, t);
        };
        for (std::uint32_t n = s.start[i]; n < s.start[i + 1]; ++n) one(s.partners[n]);
        for (std::uint32_t n = s.extra_head[i]; n != no_extra; n = s.extra_nodes[n].next) one(s.extra_nodes[n].partner);
    }

    /// For changed(): no body to skip.
    static constexpr std::uint32_t no_body = std::numeric_limits<std::uint32_t>::max();

    /// Every candidate pair that overlaps at the end of the step, each once, sorted by (first,
    /// second) as detect() would find them: the candidates hold every pair whose bodies came
    /// near each other. Only these few are sorted, not the candidates.
    std::span<const BodyPair> overlapping_pairs() {
        EventScratch& s = scratch_;
        s.all_pairs.clear();
        for (const std::vector<BodyPair>* list : {&s.pairs, &s.extra})
            for (const BodyPair& p : *list)
                if (overlap_at_end(p.first, p.second)) s.all_pairs.push_back(p);
        const auto order = [](const BodyPair& a, const BodyPair& b) {
            return a.first != b.first ? a.first < b.first : a.second < b.second;
        };
        std::sort(s.all_pairs.begin(), s.all_pairs.end(), order);
        return s.all_pairs;
    }

    /// Advances every body to the end of the step, each from the time its state refers to,
    /// and notes where each sphere ends. Returns the sum of poison() over the bodies (0 when
    /// every number is finite), taken in the same pass as the discrete step's integrate() takes
    /// it: at N = 100,000 a pass of its own over the bodies (328 bytes each) for check_finite()
    /// was 3% of the gas bench's whole profile.
    ///
    /// A movable body is advanced from its compact copy (EventBody), which holds its position
    /// and velocity as they are (note() copied them after the loop's last change to it), with
    /// advance()'s arithmetic, so the results are the same bit for bit; its kind and whether it
    /// is movable come from its EventRole. The pass then reads of each body only the 104 bytes
    /// from its position to its angular velocity (which the step writes, and poison() reads),
    /// not its inverse mass at the front nor its shape at the back: at N = 100,000 the bodies
    /// come from memory, and this leaves two of every body's five cache lines unread.
    ///
    /// The pass goes from the last body to the first, so that it ends where what follows it
    /// starts: overlapping_pairs(), the discrete stages (whose pairs come in index order) and
    /// the next step's first pass (body after body) find the first bodies, and their ends,
    /// still in the cache. Each body's result is its own, and the sum is 0 or NaN in any order.
    double finish() {
        EventScratch& s = scratch_;
        s.ends.resize(count_);
        double sum = 0.0;
        for (std::uint32_t i = count_; i-- > 0;) {
            if (i >= pass_lookahead) {
                ask_caches_for(&bodies_[i - pass_lookahead].position, moved_bytes);
                WORKBOOK_PREFETCH(&s.state[i - pass_lookahead]);
            }
            RigidBody& body = bodies_[i];
            const EventBody& state = s.state[i];
            const EventRole role = s.roles[i];
            const double tau = dt_ - state.since;
            if (role.immovable) {
                advance(body, gravity_, k_, tau);  // a kinematic body, at its set velocity and spin
            } else if (!(tau <= 0.0)) {  // as advance() tests it (a NaN goes on, and shows in poison())
                body.position = state.position + (state.velocity * tau + gravity_ * (k_ * tau * tau));  // as advance()
                body.velocity = state.velocity + gravity_ * tau;
                if (body.angular_velocity != Vector3{}) advance_free_rotation(body, tau);
            }
            // A sphere's bounding radius is its radius.
            s.ends[i] = {body.position, role.sphere ? state.bounding_radius : -1.0};
            sum += poison(body);
            // The loop is over; the copies become the next step's (EventScratch::copies_known),
            // as note(i, 0) would take them, while the body is at hand: a sphere and a box
            // take part as long as they do not spin (a plane is noted again anyway).
            s.state[i] = {body.position, body.velocity, 0.0, state.bounding_radius};
            s.roles[i].takes_part = role.sphere || body.angular_velocity == Vector3{};
        }
        return sum;
    }

private:
    static constexpr std::uint32_t no_extra = std::numeric_limits<std::uint32_t>::max();

    /// overlaps() of bodies i and j at the end of the step; two spheres from the centres and
    /// radii finish() noted (the same numbers, so the same answer), since at N = 100,000 reading
    /// the two bodies themselves missed the caches at nearly every candidate pair.
    [[nodiscard]] bool overlap_at_end(std::uint32_t i, std::uint32_t j) const {
        const SphereEnd& a = scratch_.ends[i];
        const SphereEnd& b = scratch_.ends[j];
        if (a.radius >= 0.0 && b.radius >= 0.0) return spheres_overlap(a.centre, a.radius, b.centre, b.radius);
        return overlaps(bodies_[i], bodies_[j]);
    }

    /// How far `body` may move in `left` seconds from the state it has, m: |v| left, plus for
    /// a movable body what gravity adds, (|k| + 1) |g| left^2, which also covers the motion
    /// being split into pieces at its events (each piece starts with the velocity gravity gave).
    [[nodiscard]] double can_move(std::uint32_t i, double left) const {
        const double speed_part = length(scratch_.state[i].velocity) * left;
        return scratch_.roles[i].immovable ? speed_part : speed_part + gravity_reach_ * left * left;
    }

    /// Half the sides of a box about body i's centre that holds it over `left` seconds from the
    /// state it has: its bounding radius and, along each axis, can_move()'s bound for that axis
    /// alone (infinite for a plane, whose bounding radius is). A ball that falls or bounces
    /// straight up has a box as narrow as itself across, where its widened sphere is not.
    [[nodiscard]] Vector3 box_half_sides(std::uint32_t i, double left) const {
        const EventBody& state = scratch_.state[i];
        const Vector3 speed_part = Vector3{std::abs(state.velocity.x), std::abs(state.velocity.y), std::abs(state.velocity.z)} * left;
        const Vector3 moved = scratch_.roles[i].immovable ? speed_part : speed_part + gravity_reach_along_ * (left * left);
        const double radius = state.bounding_radius;
        return moved + Vector3{radius, radius, radius};
    }

    /// Leaves out of the candidates the broad phase's pairs whose boxes are apart
    /// (boxes_apart()); a search of either body's widened sphere finds them again when its box
    /// widens (search_again()). In the bench's pile, whose balls bounce up and down, these are
    /// the neighbours beside each ball, two pairs in three, and every candidate is predicted
    /// again at each event of its bodies. In the bench's gas they are three pairs in ten, and
    /// its step was 7 to 9% slower with boxes: a step that leaves out fewer than half turns
    /// them off for the next ones (EventScratch::use_boxes).
    void leave_out_apart_pairs() {
        EventScratch& s = scratch_;
        const std::size_t found = s.pairs.size();
        std::size_t kept = 0;
        for (const BodyPair& p : s.pairs)
            if (!boxes_apart(p.first, p.second)) s.pairs[kept++] = p;
        s.pairs.resize(kept);
        if (2 * kept > found) {
            constexpr std::uint32_t pause = 16;  // 15 steps without boxes, then one that tries them
            s.use_boxes = false;
            s.steps_without_boxes = pause;
        }
    }

    /// `pairs` as lists by body (a counting sort): body i's partners are partners[start[i]]
    /// up to partners[start[i + 1]].
    void list_by_body(const std::vector<BodyPair>& pairs, std::vector<std::uint32_t>& start,
                      std::vector<std::uint32_t>& partners) const {
        start.assign(count_ + 1, 0);
        for (const BodyPair& p : pairs) ++start[p.first + 1], ++start[p.second + 1];
        for (std::uint32_t i = 0; i < count_; ++i) start[i + 1] += start[i];
        partners.resize(start[count_]);
        for (const BodyPair& p : pairs) {
            partners[start[p.first]++] = p.second;
            partners[start[p.second]++] = p.first;
        }
        for (std::uint32_t i = count_; i > 0; --i) start[i] = start[i - 1];
        start[0] = 0;
    }

    /// True when body b is among body a's candidates already (its lists are short: the
    /// bodies next to it).
    [[nodiscard]] bool is_candidate(std::uint32_t a, std::uint32_t b) const {
        const EventScratch& s = scratch_;
        for (std::uint32_t n = s.start[a]; n < s.start[a + 1]; ++n)
            if (s.partners[n] == b) return true;
        for (std::uint32_t n = s.extra_head[a]; n != no_extra; n = s.extra_nodes[n].next)
            if (s.extra_nodes[n].partner == b) return true;
        return false;
    }

    /// Makes bodies a and b candidates, found after the broad phase, unless they are already:
    /// a pair listed twice would be predicted twice at every event of its bodies.
    void add_candidate(std::uint32_t a, std::uint32_t b) {
        if (!is_candidate(a, b)) add_extra(a, b);
    }

    /// Records bodies a and b as candidates found after the broad phase.
    void add_extra(std::uint32_t a, std::uint32_t b) {
        EventScratch& s = scratch_;
        s.extra.push_back({std::min(a, b), std::max(a, b)});
        link(a, b, s.extra_head, s.extra_nodes);
    }

    /// Puts b in a's list and a in b's, of the lists by body `head` and `nodes`.
    static void link(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& head,
                     std::vector<EventScratch::ExtraNode>& nodes) {
        nodes.push_back({b, head[a]});
        head[a] = static_cast<std::uint32_t>(nodes.size() - 1);
        nodes.push_back({a, head[b]});
        head[b] = static_cast<std::uint32_t>(nodes.size() - 1);
    }

    /// Pushes the first impact of bodies a and b after time t, if any within the step.
    void predict(std::uint32_t a, std::uint32_t b, double t) {
        EventScratch& s = scratch_;
        const EventRole& role_a = s.roles[a];
        const EventRole& role_b = s.roles[b];
        if (!role_a.takes_part || !role_b.takes_part || (role_a.immovable && role_b.immovable)) return;
        if (s.events[a] >= max_events_per_body || s.events[b] >= max_events_per_body) return;
        // Two spheres are timed from the compact arrays, whose first tests (no square root)
        // pass over most pairs that cannot meet; any other pair first passes cheaply over
        // bodies too far apart to meet at the speeds they now have.
        if (role_a.sphere && role_b.sphere) {
            predict_spheres(a, seen_at(a, t), b, t);
            return;
        }
        // A sphere and a plane too: through the bodies (bodies_meet()), each prediction read
        // both and wrote them back, and a plane's events predict it again with every ball
        // above it (a pile's floor: a tenth of the balls).
        if ((role_a.sphere && role_b.plane) || (role_a.plane && role_b.sphere)) {
            predict_sphere_plane(role_a.sphere ? a : b, role_a.sphere ? b : a, t);
            return;
        }
        const double tau = may_meet(a, b) ? bodies_meet(a, b, t).value_or(no_impact) : no_impact;
        if (tau != no_impact) push_impact(a, b, t + tau);
    }

    /// predict() for two spheres that take part, sphere a seen at t as seen_at() shows it.
    /// changed() and start() write its two lines out rather than call it: the compiler would
    /// not inline it there, and the call cost what its tests do (most pairs end in
    /// cannot_meet_soon()).
    void predict_spheres(std::uint32_t a, const SphereMotion& seen_a, std::uint32_t b, double t) {
        const SpherePair pair = relative_motion(seen_a, seen_at(b, t), gravity_, k_);
        if (!cannot_meet_soon(pair, dt_ - t)) time_spheres(a, b, pair, t);
    }

    /// predict() for a sphere and a plane that take part (not both immovable), from the compact
    /// copies: sphere_plane()'s arithmetic on the numbers SeenAfter would show it, so the same
    /// answer bit for bit.
    void predict_sphere_plane(std::uint32_t sphere, std::uint32_t plane, double t) {
        if (scratch_.roles[sphere].immovable) return;
        const SphereMotion seen_sphere = seen_at(sphere, t);
        const SphereMotion seen_plane = seen_at(plane, t);
        const PlaneMotion seen{seen_plane.position, seen_plane.velocity, scratch_.normals[plane]};
        const double tau =
            lowest_point_plane(seen_sphere.position, seen_sphere.velocity, seen_sphere.radius, seen, gravity_, k_, dt_ - t)
                .value_or(no_impact);
        if (tau != no_impact) push_impact(sphere, plane, t + tau);
    }

    /// The rest of predict_spheres() for a pair that cannot_meet_soon() did not rule out.
    void time_spheres(std::uint32_t a, std::uint32_t b, const SpherePair& pair, double t) {
        const double tau = first_touch(pair, dt_ - t);
        if (tau != no_impact) push_impact(a, b, t + tau);
    }

    /// Queues an impact of bodies a and b at time `when`, as their event counts stand.
    void push_impact(std::uint32_t a, std::uint32_t b, double when) {
        const EventScratch& s = scratch_;
        const std::uint32_t i = std::min(a, b), j = std::max(a, b);
        enqueue({when, i, j, s.events[i], s.events[j]});
    }

    /// Puts event e in the heap if its slice of the step is open, else in its slice's list.
    void enqueue(const ImpactEvent& e) {
        EventScratch& s = scratch_;
        const std::uint32_t slice = slice_of(e.t);
        if (slice < opened_) {
            s.heap.push_back(e);
            std::push_heap(s.heap.begin(), s.heap.end(), Later{});
            most_in_heap_ = std::max(most_in_heap_, s.heap.size());
            return;
        }
        s.pending.push_back({e, s.slice_head[slice]});
        s.slice_head[slice] = static_cast<std::uint32_t>(s.pending.size() - 1);
    }

    /// The slice of the step time t falls in: floor(t / slice width), the last for t = dt
    /// (and for anything rounding puts beyond it, or a NaN). Never smaller for a later time.
    [[nodiscard]] std::uint32_t slice_of(double t) const {
        const double x = t * slices_per_second_;
        return x < static_cast<double>(slice_count_ - 1) ? static_cast<std::uint32_t>(x) : slice_count_ - 1;
    }

    /// Moves the next slice's events into the (used up) run, sorted earliest first. The slice's
    /// list holds them newest first; turned round, in the order they were queued, they are
    /// mostly in order already, and are sorted only when they are not. In the bench's pile the
    /// slices that hold more than one event are about a dozen a step, each the impacts of one
    /// moment (thousands at N = 100,000), queued by the events before them in the order of their
    /// bodies: all but one in 400 were in order, and sorting them was 2% of the step. (Events
    /// that Earlier leaves in no order are of the same pair at the same moment: those predicted
    /// with other event counts than the one that holds are stale, the rest are the same event,
    /// so their order changes nothing.)
    void open_slice() {
        EventScratch& s = scratch_;
        s.run.clear();
        s.run_next = 0;
        for (std::uint32_t n = s.slice_head[opened_]; n != no_node; n = s.pending[n].next) s.run.push_back(s.pending[n].event);
        std::reverse(s.run.begin(), s.run.end());
        if (!std::is_sorted(s.run.begin(), s.run.end(), Earlier{})) std::sort(s.run.begin(), s.run.end(), Earlier{});
        longest_run_ = std::max(longest_run_, s.run.size());
        ++opened_;
    }

    /// False when bodies a and b (not planes) cannot meet at the speeds they now have: their
    /// stored centres are further apart than both can move in what is left of the step (one
    /// comparison, as cheap as the discrete loop's overlap test). Always true with a plane.
    [[nodiscard]] bool may_meet(std::uint32_t a, std::uint32_t b) const {
        const EventScratch& s = scratch_;
        if (s.roles[a].plane || s.roles[b].plane) return true;
        const EventBody& state_a = s.state[a];
        const EventBody& state_b = s.state[b];
        const double within = state_a.bounding_radius + state_b.bounding_radius + can_move(a, dt_ - state_a.since) +
                              can_move(b, dt_ - state_b.since);
        return length_squared(state_a.position - state_b.position) <= within * within * (1.0 + tolerances::conservative_slack);
    }

    /// Sphere i as time_of_impact() must see it at time t, from the compact arrays alone: as
    /// SeenAfter shows a body (the same arithmetic, so two spheres' time of impact is the same).
    [[nodiscard]] SphereMotion seen_at(std::uint32_t i, double t) const {
        const EventBody& state = scratch_.state[i];
        SphereMotion seen{state.position, state.velocity, state.bounding_radius, scratch_.roles[i].immovable};
        const double s = t - state.since;
        if (s <= 0.0) return seen;
        if (seen.immovable) {
            seen.position += state.velocity * s;
            return seen;
        }
        seen.position += state.velocity * s + gravity_ * (k_ * s * s);
        seen.velocity += gravity_ * (2.0 * k_ * s);
        return seen;
    }

    /// Any other pair's time of impact after t, from the bodies themselves, each moved to t in place.
    [[nodiscard]] std::optional<double> bodies_meet(std::uint32_t a, std::uint32_t b, double t) const {
        const SeenAfter seen_a(bodies_[a], gravity_, k_, t - scratch_.state[a].since);
        const SeenAfter seen_b(bodies_[b], gravity_, k_, t - scratch_.state[b].since);
        return time_of_impact(bodies_[a], bodies_[b], gravity_, k_, dt_ - t);
    }

    /// How far body i, as it now moves, may get from where it started the step by the end. Its
    /// path is x + v tau + k g tau^2 over what is left of the step; the line x + v tau gets
    /// furthest from the origin at one of its ends (the distance to a point is convex along a
    /// line), and gravity adds at most what can_move() allows it. The looser bound |x - origin|
    /// + |v| left counted a body that an impact sends back where it came from as going on:
    /// in a pile most impacts turn a ball round, and each such ball was searched again.
    [[nodiscard]] double needs_reach(std::uint32_t i, double t) const {
        const EventBody& state = scratch_.state[i];
        const double left = dt_ - t;
        const Vector3 from = state.position - scratch_.reach[i].origin;
        const double line = std::max(length(from), length(from + state.velocity * left));
        return scratch_.roles[i].immovable ? line : line + gravity_reach_ * left * left;
    }

    /// needs_reach() axis by axis: how far body i, as it now moves, may get from where it
    /// started the step along each axis by the end (gravity along each axis adding at most
    /// what can_move() allows it along that axis).
    [[nodiscard]] Vector3 needs_reach_along_axes(std::uint32_t i, double t) const {
        const EventBody& state = scratch_.state[i];
        const double left = dt_ - t;
        const Vector3 from = state.position - scratch_.reach[i].origin;
        const Vector3 to = from + state.velocity * left;
        const Vector3 line{std::max(std::abs(from.x), std::abs(to.x)), std::max(std::abs(from.y), std::abs(to.y)),
                           std::max(std::abs(from.z), std::abs(to.z))};
        return scratch_.roles[i].immovable ? line : line + gravity_reach_along_ * (left * left);
    }

    /// True when body i may leave the box its candidates were last checked against.
    [[nodiscard]] bool leaves_box(std::uint32_t i, double t) const {
        if (!boxes_) return false;
        const Vector3 needs = needs_reach_along_axes(i, t);
        const Vector3& half = scratch_.reach[i].half_sides;
        const double radius = scratch_.state[i].bounding_radius;
        return needs.x + radius > half.x || needs.y + radius > half.y || needs.z + radius > half.z;
    }

    /// True when body i may leave the widened sphere its candidates were found for, or its box.
    [[nodiscard]] bool outran(std::uint32_t i, double t) const {
        if (scratch_.roles[i].immovable) return false;
        return (!surely_within_reach(i, t) && needs_reach(i, t) > scratch_.reach[i].reach) || leaves_box(i, t);
    }

    /// True when needs_reach(i, t) is certainly no more than body i's reach, found from squared
    /// lengths, without needs_reach()'s two square roots: its furthest point on the line is
    /// then further inside the reach, less what gravity adds, than rounding could account for
    /// (a relative 1e-9, against rounding errors of about 1e-16). At most events the body is
    /// well within its reach (in the pile 6 of 7), and the square roots were most of the test.
    /// False when it is not certain, and needs_reach() decides (the same answer as before).
    [[nodiscard]] bool surely_within_reach(std::uint32_t i, double t) const {
        const EventBody& state = scratch_.state[i];
        const double left = dt_ - t;
        const Vector3 from = state.position - scratch_.reach[i].origin;
        const double furthest_squared = std::max(length_squared(from), length_squared(from + state.velocity * left));
        const double room = scratch_.reach[i].reach - gravity_reach_ * left * left;
        return room > 0.0 && furthest_squared < room * room * (1.0 - 1e-9);
    }

    /// True when the step uses boxes and bodies a and b cannot meet within it because their
    /// boxes (EventReach::half_sides) are apart along some axis, with a relative slack for
    /// rounding as the spheres' test has. Never for a plane, whose box is infinite (its
    /// bounding radius is).
    [[nodiscard]] bool boxes_apart(std::uint32_t a, std::uint32_t b) const {
        if (!boxes_) return false;
        const Vector3& p = scratch_.reach[a].origin;
        const Vector3& q = scratch_.reach[b].origin;
        const Vector3& p_half = scratch_.reach[a].half_sides;
        const Vector3& q_half = scratch_.reach[b].half_sides;
        const auto apart = [](double x, double y, double half_x, double half_y) {
            constexpr double slack = tolerances::conservative_slack;
            return std::abs(x - y) > (half_x + half_y) * (1.0 + slack) + slack * (std::abs(x) + std::abs(y));
        };
        return apart(p.x, q.x, p_half.x, q_half.x) || apart(p.y, q.y, p_half.y, q_half.y) || apart(p.z, q.z, p_half.z, q_half.z);
    }

    /// Adds as candidates of body i every body whose widened sphere, as the broad phase has it
    /// now (gathered at the start of the step, or widened since), comes within `radius` of i's
    /// centre then, and whose box meets i's. With boxes, the grid is searched only where a box
    /// that meets i's can be (search_box()).
    ///
    /// A body found here whose box is apart from i's is not kept anywhere: if either box widens
    /// later, that body searches again and finds the other. Its search is never narrower than
    /// the sphere it has in the broad phase (search_again() widens it there first), and the
    /// other's sphere there is never narrower than the one it searched with here, so the same
    /// test on the same or larger numbers holds (the sums and the comparison round the same
    /// way). Lists of such pairs by body, walked when a box widened, found nothing that search
    /// did not.
    void add_near(std::uint32_t i, double radius) {
        EventScratch& s = scratch_;
        s.near.clear();
        s.broad_phase.bodies_near(s.proxies, s.reach[i].origin, radius, s.near, search_box(i));
        for (const std::uint32_t j : s.near) {
            if (j == i || (s.roles[i].immovable && s.roles[j].immovable)) continue;
            if (!boxes_apart(i, j)) add_candidate(i, j);
        }
    }

    /// For a body that outran its widened sphere or its box (outran()): widens the sphere's
    /// reach to a tenth more than it now needs (when it outran that), and the sides of the box it
    /// may leave, and adds as candidates the bodies whose widened spheres its own meets, from
    /// the cells near it, and whose boxes meet its own. Why a tenth:
    /// every candidate is predicted again at each later event of its bodies, so a wide search
    /// costs at every event after it. Twice what it needs took in so many that the pile's step
    /// was 10% slower than with a quarter more; once predictions passed over receding and slow
    /// pairs before the square root, a tenth more was faster again than a quarter (by 5 to 8% in
    /// the pile at N = 10,000 and the gas at 100,000, the same within the noise elsewhere), and
    /// exactly what it needs, searched again at the next speed-up, was no faster than a tenth.
    void search_again(std::uint32_t i, double t) {
        EventScratch& s = scratch_;
        EventReach& reach = s.reach[i];
        const double needs = needs_reach(i, t);
        if (needs > reach.reach) {
            reach.reach = 1.1 * needs;
            // Later searches of other bodies find this one by its new reach (BroadPhase::widen()).
            s.broad_phase.widen(s.proxies, i, s.state[i].bounding_radius + reach.reach);
        }
        widen_box(i, t);
        // The search finds again the pairs the broad phase left out for their boxes, and those
        // that earlier searches (of this body or of others) left out for theirs (add_near()).
        add_near(i, s.state[i].bounding_radius + reach.reach);
    }

    /// Half the sides of the box about body i's origin outside which no body's box meets i's
    /// (boxes_apart() says apart for a centre beyond it), for the search of the grid: i's half
    /// side and the largest of any body's along each axis (largest_half_sides_), with room for
    /// the slack of boxes_apart() and for rounding. Unbounded in a step without boxes.
    ///
    /// Most searches again are of a ball that an impact sped up beyond its sphere, and found
    /// (over the bench's pile of 100,000) six bodies each, four of them beside it with their
    /// boxes apart: the grid was walked over the whole widened sphere for about one new
    /// candidate in 700 searches. In a pile whose balls move up and down, the box narrows the
    /// cells walked across, and bodies_near() leaves out the balls beside it before the event
    /// loop reads their boxes (two bodies found per search rather than six).
    [[nodiscard]] Vector3 search_box(std::uint32_t i) const {
        if (!boxes_) return BroadPhase::unbounded;
        const Vector3& origin = scratch_.reach[i].origin;
        const Vector3& half = scratch_.reach[i].half_sides;
        // Not apart along an axis: |x - y| <= (h_i + h_j)(1 + slack) + slack (|x| + |y|), with
        // h_j no more than the largest and |y| no more than |x| + |x - y|; so |x - y| is at most
        // ((h_i + largest)(1 + slack) + 2 slack |x|) / (1 - slack), which (1 + 4 slack) covers
        // with room for the rounding of both sides.
        constexpr double slack = tolerances::conservative_slack;
        const auto along = [](double x, double own, double largest) {
            return ((own + largest) * (1.0 + slack) + 2.0 * slack * std::abs(x)) * (1.0 + 4.0 * slack);
        };
        const Vector3& largest = largest_half_sides_;
        return {along(origin.x, half.x, largest.x), along(origin.y, half.y, largest.y), along(origin.z, half.z, largest.z)};
    }

    /// Keeps largest_half_sides_ at least `half` along each axis; a NaN makes it infinite, so
    /// that search_box() narrows nothing (the search then walks the widened sphere's cells, as
    /// without boxes).
    void note_half_sides(const Vector3& half) {
        constexpr double infinite = std::numeric_limits<double>::infinity();
        const auto keep = [](double h, double& largest) {
            if (!(h <= largest)) largest = std::isnan(h) ? infinite : h;
        };
        keep(half.x, largest_half_sides_.x);
        keep(half.y, largest_half_sides_.y);
        keep(half.z, largest_half_sides_.z);
    }

    /// Widens each side of body i's box that it may now leave to its widened sphere (or a tenth
    /// more than it needs, when rounding puts that beyond): a side left once is not left again
    /// before the sphere is, so a body whose impacts turn it searches at most three times more
    /// per step than with spheres alone, and the sides it does not leave stay narrow.
    void widen_box(std::uint32_t i, double t) {
        if (!boxes_) return;
        EventReach& reach = scratch_.reach[i];
        Vector3& half_sides = reach.half_sides;
        const Vector3 needs = needs_reach_along_axes(i, t);
        const double radius = scratch_.state[i].bounding_radius;
        const auto widen = [&](double need, double& half) {
            if (need + radius > half) half = radius + std::max(reach.reach, 1.1 * need);
        };
        widen(needs.x, half_sides.x);
        widen(needs.y, half_sides.y);
        widen(needs.z, half_sides.z);
        note_half_sides(half_sides);
    }

    std::span<RigidBody> bodies_;
    EventScratch& scratch_;
    Vector3 gravity_;
    double k_;
    double dt_;
    /// (|k| + 1) |g|, for can_move(): taken once per step rather than once per call (a square
    /// root that the compiler cannot hoist out of the loops that write the scratch arrays).
    double gravity_reach_;
    /// The same along each axis, (|k| + 1) |g_axis|, for the boxes (box_half_sides()).
    Vector3 gravity_reach_along_;
    /// How many slices the step is cut into for the queue of events: one per 8 bodies, so
    /// that a slice holds a few events in a pile (0.65 per body and step) and fewer in a gas.
    std::uint32_t slice_count_;
    double slices_per_second_;   ///< slice_count_ / dt
    std::uint32_t opened_ = 0;   ///< the slices whose events are in the heap (the first ones)
    std::size_t most_in_heap_ = 0;  ///< the most events the heap held at once this step
    std::size_t longest_run_ = 0;   ///< the most events a slice held this step
    static constexpr std::uint32_t no_node = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t count_;
    bool boxes_;  ///< this step checks boxes as well as widened spheres (EventScratch::use_boxes)
    /// With boxes: the largest half side along each axis of any body's box but a plane's (the
    /// bodies the grid holds), as widened so far this step; see search_box().
    Vector3 largest_half_sides_{};
};

/// Moves the two bodies of `event` to its moment and answers their contact there with the
/// model's responder; returns the kinetic energy the response changed, when `measure_energy`
/// (else 0: four kinetic energies per event, spinning bodies' through their inertia, for a
/// probe that a run without it reads as 0, as the discrete step's does).
double answer_impact(std::span<RigidBody> bodies, const ImpactEvent& event, EventLoop& loop, const ResponseModel& model,
                     const FiniteCheck& check, EventScratch& scratch, bool measure_energy) {
    std::uint32_t first = event.i, second = event.j;
    loop.advance_to(first, event.t);
    loop.advance_to(second, event.t);
    // Body 2 of a pair with a plane is the plane, and of a sphere and a box the box, as everywhere else.
    if (bodies[first].shape.kind == ShapeKind::plane ||
        (bodies[first].shape.kind == ShapeKind::box && bodies[second].shape.kind == ShapeKind::sphere))
        std::swap(first, second);
    const Contact contact = touching_contact(bodies[first], first, bodies[second], second);
    const double before = measure_energy ? kinetic_energy(bodies[first]) + kinetic_energy(bodies[second]) : 0.0;
    model.respond(bodies[first], bodies[second], contact);
    const double change = measure_energy ? kinetic_energy(bodies[first]) + kinetic_energy(bodies[second]) - before : 0.0;
    scratch.contacts.push_back(contact);
    if (check.on && !(poison(bodies[first]) + poison(bodies[second]) == 0.0))
        check_finite(bodies, check.names, check.step, "event: respond");
    loop.note(first, event.t);  // the response changed the two bodies
    loop.note(second, event.t);
    // The pair itself is predicted again once, with the second body: predicted with the first,
    // it would carry the second's count from before the event and be passed over as stale.
    loop.changed(first, event.t, second);
    loop.changed(second, event.t, EventLoop::no_body);
    return change;
}

}  // namespace

void advance_whole_step(std::span<RigidBody> bodies, const EventMotion& motion) {
    for (RigidBody& body : bodies) advance(body, motion.gravity, motion.k, motion.dt);
}

ImpactsAnswered move_impact_to_impact(std::span<RigidBody> bodies, const EventMotion& motion, const ResponseModel& model,
                                      const FiniteCheck& check, EventScratch& scratch, bool measure_energy) {
    const auto count = static_cast<std::uint32_t>(bodies.size());
    EventLoop loop(bodies, motion, scratch);
    loop.start();
    double energy_change = 0.0;
    const std::size_t event_budget = 8 + 2 * std::size_t{count};
    for (std::size_t events = 0; events < event_budget; ++events) {
        const std::optional<ImpactEvent> event = loop.next();
        if (!event) break;
        energy_change += answer_impact(bodies, *event, loop, model, check, scratch, measure_energy);
    }
    loop.keep_room();
    const double poisoned = loop.finish();  // every body to the end of the step
    if (check.on && !(poisoned == 0.0)) check_finite(bodies, check.names, check.step, "event: advance");
    const std::span<const BodyPair> overlapping = loop.overlapping_pairs();
    scratch.copies_known = true;  // finish() left them, and overlapping_pairs() the bodies to note again
    return {energy_change, overlapping, scratch.broad_phase.has_grid()};
}

}  // namespace workbook
