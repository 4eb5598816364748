// Chapter 4 over its whole legal domain (chapters/angular-impulse/angular-impulse.hpp): a
// thousand sampled legal inputs per function and step, each judged against the reference's
// answer computed here from the checker's own copy of the input (see sampling.hpp).
#include <catch2/catch_test_macros.hpp>

#include <algorithm>

#include "../reference.hpp"
#include "../../steps/angular_impulse_laws.hpp"
#include "angular-impulse.hpp"
#include "sampling.hpp"
#include "workbook/restitution.hpp"

using namespace workbook;
using namespace workbook::domain;
namespace laws = workbook::angular_impulse_laws;
namespace reference = workbook::reference_angular_impulse;

namespace {

/// A spinning body: movable with inverse mass `w`, or pinned (at rest or kinematic, its
/// inertia_body zero or not); velocity and angular velocity drawn over their domain.
RigidBody draw_body(SeededRandom& random, double w, bool immovable) {
    RigidBody b = movable(random, w);
    b.position = position(random);
    b.velocity = velocity(random);
    const Vector3 spin = velocity(random);
    const double size = body_size(b);
    b.angular_velocity = spin / size;
    if (immovable) pin(random, b, 0.5, true);
    return b;
}

/// A point near `body`: its centre (0.05), or up to a few sizes away in any direction.
Vector3 point_near(SeededRandom& random, const RigidBody& body) {
    if (chance(random, 0.05)) return body.position;
    const Vector3 d = random.direction();
    const double r = body_size(body) * decades(random, -2.0, 0.5);
    return body.position + d * r;
}

/// Two bodies near each other with `pinned` immovable ones, and a contact point between them
/// whose normal is not the line through the centres.
void draw_pair(SeededRandom& random, Case& c, int pinned) {
    double w1 = 1.0;
    double w2 = 1.0;
    pair_masses(random, w1, w2);
    const bool first = chance(random, 0.5);
    const bool pin1 = pinned == 2 || (pinned == 1 && first);
    const bool pin2 = pinned == 2 || (pinned == 1 && !first);
    c.body1 = draw_body(random, w1, pin1);
    c.body2 = draw_body(random, w2, pin2);
    c.point = point_near(random, c.body1);
    const Vector3 d = random.direction();
    const double r = body_size(c.body2) * decades(random, -2.0, 0.5);
    c.body2.position = c.point + d * r;
    c.normal = unit_normal(random);
    c.contact.normal = c.normal;
    c.contact.point_count = 0;
    c.contact.penetration = 0.0;
    const double depth = chance(random, 0.3) ? 0.0 : decades(random, -6.0, -2.0);
    c.contact.add_point(c.point, depth);
}

/// u at `point` along `normal`, from the checker's copy.
double point_normal_velocity(const Case& c, const Vector3& point, const Vector3& normal) {
    return dot(reference::point_velocity(c.body1, point) - reference::point_velocity(c.body2, point), normal);
}

/// The rounding of impulse_denominator: the terms (w1 + w2) |n|^2 and |I^-1| |r|^2 |n|^2, the
/// inverse amplified by its condition.
double denominator_tolerance(const Case& c, const Vector3& point, const Vector3& normal) {
    double scale = (c.body1.inverse_mass + c.body2.inverse_mass) * length_squared(normal);
    for (const RigidBody* b : {&c.body1, &c.body2}) {
        const double r = length(point - b->position) + length(point) + length(b->position);
        scale += inverse_reach(*b) * r * r * length_squared(normal);
    }
    return rounding(scale, 64.0);
}

/// The answer of an impulse of size about `j` at `point`: per body, the tolerance of v and w.
struct BodyTolerance {
    double v = 0.0;
    double w = 0.0;
};

BodyTolerance impulse_tolerance(const RigidBody& b, const Vector3& point, double j, double dj, double ulps = 64.0) {
    const double r = length(point - b.position) + length(point) + length(b.position);
    return {rounding(length(b.velocity) + b.inverse_mass * j, ulps) + b.inverse_mass * dj,
            rounding(length(b.angular_velocity) + inverse_reach(b) * r * j, ulps) + inverse_reach(b) * r * dj};
}

/// A contact like the ones bodies make: body 1 movable, and every point within four sizes of
/// the centre of each movable body. (Far outside, a point's lever arm makes the several-point
/// problem so ill-conditioned that no solver in double, the reference's included, decides it.)
bool manifold_like(const Case& c) {
    if (c.body1.is_immovable() || c.contact.point_count < 2) return false;
    for (const RigidBody* b : {&c.body1, &c.body2}) {
        if (b->is_immovable()) continue;
        for (std::size_t i = 0; i < c.contact.point_count; ++i)
            if (length(c.contact.points[i].position - b->position) > 4.0 * body_size(*b)) return false;
    }
    return true;
}

/// Both bodies' v and w against the reference's, immovable ones exactly.
Verdict compare_motion(const Case& c, const RigidBody& a1, const RigidBody& a2, const RigidBody& e1, const RigidBody& e2,
                       const BodyTolerance& t1, const BodyTolerance& t2, const Law& law, const std::string& call) {
    for (int side = 1; side <= 2; ++side) {
        const RigidBody& was = side == 1 ? c.body1 : c.body2;
        const RigidBody& is = side == 1 ? a1 : a2;
        const RigidBody& expected = side == 1 ? e1 : e2;
        const BodyTolerance& t = side == 1 ? t1 : t2;
        const std::string who = "body " + std::to_string(side) + "'s ";
        if (was.is_immovable()) {
            if (Verdict v = compare(laws::immovable, "the immovable " + who + "velocity after " + call, "m/s", was.velocity, is.velocity, 0.0);
                v.failed())
                return v;
            if (Verdict v = compare(laws::immovable, "the immovable " + who + "angular velocity after " + call, "rad/s",
                                    was.angular_velocity, is.angular_velocity, 0.0);
                v.failed())
                return v;
            continue;
        }
        if (Verdict v = compare(law, who + "velocity after " + call, "m/s", expected.velocity, is.velocity, t.v); v.failed()) return v;
        if (Verdict v = compare(law, who + "angular velocity after " + call, "rad/s", expected.angular_velocity, is.angular_velocity, t.w);
            v.failed())
            return v;
    }
    return {};
}

Approach approach_kind(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.6) return Approach::approaching;
    if (pick < 0.75) return Approach::creeping;
    if (pick < 0.9) return Approach::separating;
    return Approach::resting;
}

/// Sets body 1's velocity so that the point `p` moves as `how` says along the normal.
bool set_point_motion(SeededRandom& random, Case& c, const Vector3& p, Approach how) {
    RigidBody& b = c.body1.is_immovable() ? c.body2 : c.body1;
    if (b.is_immovable()) return true;  // two immovable bodies: as drawn
    const double s = how == Approach::creeping ? decades(random, -12.0, -6.0) : speed(random);
    if (how == Approach::resting) {
        c.body1.velocity = c.body2.velocity = c.body1.angular_velocity = c.body2.angular_velocity = Vector3{};
        return true;
    }
    if (how == Approach::creeping) {
        // Small bodies at small speeds: the whole motion about as slow as the approach.
        for (RigidBody* x : {&c.body1, &c.body2}) {
            if (x->is_immovable()) continue;
            x->velocity = x->velocity * (s / std::max(length(x->velocity), 1e-300));
            x->angular_velocity = x->angular_velocity * (s / std::max(length(x->angular_velocity) * body_size(*x), 1e-300));
        }
        if (c.body1.is_immovable() || c.body2.is_immovable()) {
            RigidBody& fixed = c.body1.is_immovable() ? c.body1 : c.body2;
            fixed.velocity = fixed.velocity * (s / std::max(length(fixed.velocity), 1e-300));
            fixed.angular_velocity = Vector3{};
        }
    }
    const double u = point_normal_velocity(c, p, c.contact.normal);
    if (u == 0.0) return false;
    const bool want_approach = how == Approach::approaching || how == Approach::creeping;
    if ((u < 0.0) != want_approach) {
        c.contact.normal = -c.contact.normal;
        c.normal = c.contact.normal;
    }
    return true;
}

/// A face, an edge or a few points of body 1 resting on body 2 (the ground, kinematic or not,
/// or another body): 2 to 4 points in the plane across the normal below body 1's centre. Body 1
/// falls and spins, so that some points approach while others rest or recede.
bool draw_manifold(SeededRandom& random, Case& c) {
    double w1 = 1.0;
    double w2 = 1.0;
    pair_masses(random, w1, w2);
    const int pick = int(random.uniform(0.0, 3.0));  // 0: ground at rest, 1: kinematic ground, 2: movable body
    c.body1 = draw_body(random, w1, false);
    c.body2 = draw_body(random, w2, pick < 2);
    if (pick == 0) c.body2.velocity = c.body2.angular_velocity = Vector3{};
    const Vector3 n = unit_normal(random);
    c.contact.normal = n;
    const double size = body_size(c.body1);
    if (pick == 2) {  // another body of about the same size
        const double other = size * random.uniform(0.5, 2.0);
        const double grow = other / body_size(c.body2);
        c.body2.inertia_body = c.body2.inertia_body * (grow * grow);
        c.body2.update_world_inertia();
    }
    const Vector3 t1 = normalized(cross(n, random.direction()));
    const Vector3 t2 = cross(n, t1);
    const double a = size * random.uniform(0.2, 1.0);
    const double b = size * random.uniform(0.2, 1.0);
    const double h = size * random.uniform(0.2, 1.0);
    const Vector3 face = c.body1.position - n * h;
    c.body2.position = face - n * (size * random.uniform(0.5, 2.0));
    const double shape = random.uniform(0.0, 1.0);
    const int count = shape < 0.4 ? 4 : shape < 0.7 ? 2 : 3;
    const double corners[4][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
    c.contact.point_count = 0;
    c.contact.penetration = 0.0;
    const double zero = random.uniform(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
        const double depth = zero < 0.3 ? 0.0 : decades(random, -6.0, -2.0);
        c.contact.add_point(face + t1 * (corners[i][0] * a) + t2 * (corners[i][1] * b), depth);
    }
    // Falls onto the face at speed s, sliding, and rocks at up to 3 s / size.
    const double s = chance(random, 0.15) ? decades(random, -12.0, -6.0) : speed(random);
    const Vector3 across = cross(n, random.direction());
    const double slide_speed = s * random.uniform(0.0, 2.0);
    const Vector3 slide = across * slide_speed;
    c.body1.velocity = c.body2.velocity - n * s + slide;
    const Vector3 rock = random.direction();
    const double spin = chance(random, 0.2) ? 0.0 : s / size * random.uniform(0.0, 3.0);
    c.body1.angular_velocity = rock * spin;
    if (pick == 2) c.body2.angular_velocity = Vector3{};
    c.normal = n;
    return true;
}

/// The largest lever arm of a contact's points from `b`'s centre.
double reach(const Contact& contact, const RigidBody& b) {
    double r = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const Vector3& p = contact.points[i].position;
        r = std::max(r, length(p - b.position) + length(p) + length(b.position));
    }
    return r;
}

/// The longest lever arm of a contact's points about `b`'s centre.
double lever(const Contact& contact, const RigidBody& b) {
    double r = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) r = std::max(r, length(contact.points[i].position - b.position));
    return r;
}

}  // namespace

TEST_CASE("sampled bodies, turned any way, inertia not diagonal, immovable ones with inertia: I_world^-1",
          "[angular-impulse][step:1:world-inverse-inertia][points:3]") {
    sample(
        401, {.body2 = false, .spin = true},
        [](SeededRandom& random, Case& c) {
            const double w = inverse_mass(random);
            const bool immovable = chance(random, 0.15);
            c.body1 = draw_body(random, w, immovable);
            return true;
        },
        [](const Case& c) {
            const Matrix3 actual = angular_impulse::world_inverse_inertia(c.body1);
            const Matrix3 expected = reference::world_inverse_inertia(c.body1);
            const double tolerance = rounding(inverse_reach(c.body1), 64.0);
            const Law& law = c.body1.is_immovable() ? laws::immovable : laws::world_inertia;
            for (int r = 0; r < 3; ++r)
                if (Verdict v = compare(law, "row " + std::to_string(r) + " of world_inverse_inertia", "1/(kg m^2)", expected.row(r),
                                        actual.row(r), tolerance);
                    v.failed())
                    return v;
            return Verdict{};
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled spinning bodies, kinematic ones among them, and points anywhere: the point velocity",
          "[angular-impulse][step:2:point-velocity][points:3]") {
    sample(
        402, {.body2 = false, .point = true, .spin = true},
        [](SeededRandom& random, Case& c) {
            const double w = inverse_mass(random);
            const bool immovable = chance(random, 0.2);
            c.body1 = draw_body(random, w, immovable);
            c.point = point_near(random, c.body1);
            return true;
        },
        [](const Case& c) {
            const Vector3 actual = angular_impulse::point_velocity(c.body1, c.point);
            const Vector3 expected = reference::point_velocity(c.body1, c.point);
            return compare(laws::point_velocity, "point_velocity", "m/s", expected, actual, rounding(point_speed_terms(c.body1, c.point)));
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled pairs, points off the line of centres: the impulse denominator", "[angular-impulse][step:3:impulse-size][points:2]") {
    sample(
        403, {.point = true, .normal = true, .spin = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.3, 0.05);
            draw_pair(random, c, count);
            return true;
        },
        [](const Case& c) {
            const double actual = angular_impulse::impulse_denominator(c.body1, c.body2, c.point, c.normal);
            const double expected = reference::impulse_denominator(c.body1, c.body2, c.point, c.normal);
            return compare(laws::restitution, "impulse_denominator", "1/kg", expected, actual, denominator_tolerance(c, c.point, c.normal));
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled pairs, e from 0 to 1, creeping and kinematic ones among them: the impulse size",
          "[angular-impulse][step:3:impulse-size][points:3]") {
    sample(
        404, {.point = true, .normal = true, .restitution = true, .spin = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.3, 0.05);
            draw_pair(random, c, count);
            c.restitution = draw_restitution(random);
            const Approach how = approach_kind(random);
            return set_point_motion(random, c, c.point, how);
        },
        [](const Case& c) {
            const double actual = angular_impulse::impulse_magnitude(c.body1, c.body2, c.point, c.normal, c.restitution);
            const double expected = reference::impulse_magnitude(c.body1, c.body2, c.point, c.normal, c.restitution);
            const double k = reference::impulse_denominator(c.body1, c.body2, c.point, c.normal);
            if (k == 0.0) return compare(laws::restitution, "impulse_magnitude of two immovable bodies", "kg m/s", 0.0, actual, 0.0);
            const double u = point_normal_velocity(c, c.point, c.normal);
            const double terms = point_speed_terms(c.body1, c.point) + point_speed_terms(c.body2, c.point);
            const double tolerance =
                (1.0 + c.restitution) * (rounding(terms) / k + std::abs(u) * denominator_tolerance(c, c.point, c.normal) / (k * k));
            return compare(laws::restitution, "impulse_magnitude", "kg m/s", expected, actual, tolerance);
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled impulses at points anywhere, on movable, immovable and kinematic bodies", "[angular-impulse][step:4:apply-impulse][points:3]") {
    sample(
        405, {.point = true, .impulse = true, .spin = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.3, 0.05);
            draw_pair(random, c, count);
            const RigidBody& mover = c.body1.is_immovable() ? c.body2 : c.body1;
            const double m = mover.is_immovable() ? 1.0 : mover.mass();
            const Vector3 d = random.direction();
            const double s = speed(random);
            c.impulse = chance(random, 0.05) ? Vector3{} : d * (s * m);
            return true;
        },
        [](const Case& c) {
            RigidBody a1 = c.body1;
            RigidBody a2 = c.body2;
            angular_impulse::apply_impulse(a1, a2, c.point, c.impulse);
            RigidBody e1 = c.body1;
            RigidBody e2 = c.body2;
            reference::apply_impulse(e1, e2, c.point, c.impulse);
            if (Verdict v = unchanged(c, a1, a2, {.velocity = true, .angular_velocity = true}, "apply_impulse"); v.failed()) return v;
            const double j = length(c.impulse);
            return compare_motion(c, a1, a2, e1, e2, impulse_tolerance(c.body1, c.point, j, 0.0),
                                  impulse_tolerance(c.body2, c.point, j, 0.0), laws::impulse_response, "apply_impulse");
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled one-point contacts off the line of centres: the response", "[angular-impulse][step:5:one-point][points:3]") {
    sample(
        406, {.contact = true, .spin = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.3, 0.05);
            draw_pair(random, c, count);
            const Approach how = approach_kind(random);
            return set_point_motion(random, c, c.point, how);
        },
        [](const Case& c) {
            RigidBody a1 = c.body1;
            RigidBody a2 = c.body2;
            angular_impulse::resolve(a1, a2, c.contact);
            RigidBody e1 = c.body1;
            RigidBody e2 = c.body2;
            reference::resolve(e1, e2, c.contact);
            if (Verdict v = unchanged(c, a1, a2, {.velocity = true, .angular_velocity = true}, "resolve"); v.failed()) return v;
            const Vector3 p = c.contact.points[0].position;
            const Vector3 n = c.contact.normal;
            const double k = reference::impulse_denominator(c.body1, c.body2, p, n);
            const double u = point_normal_velocity(c, p, n);
            const double e = combined_restitution(c.body1, c.body2);
            const bool pushes = u < 0.0 && k > 0.0;
            const double j = pushes ? -(1.0 + e) * u / k : 0.0;
            const double terms = point_speed_terms(c.body1, p) + point_speed_terms(c.body2, p);
            const double dj = pushes ? (1.0 + e) * (rounding(terms) / k + std::abs(u) * denominator_tolerance(c, p, n) / (k * k)) : 0.0;
            const Law& law = u >= 0.0 ? laws::separating : laws::restitution;
            // resolve() may reach one point through the several-point solver: a sweep that meets
            // the point a few thousand times adds a rounding each time (1e4 ulps).
            const double ulps = 16384.0;
            return compare_motion(c, a1, a2, e1, e2, impulse_tolerance(c.body1, p, j, dj, ulps),
                                  impulse_tolerance(c.body2, p, j, dj, ulps), law, "resolve");
        },
        [](const Case& c) { return c.contact.point_count == 1; });
}

TEST_CASE("sampled faces, edges and rocking boxes: several points resolved together", "[angular-impulse][step:6:several-points][points:3]") {
    sample(
        407, {.contact = true, .spin = true},
        [](SeededRandom& random, Case& c) { return draw_manifold(random, c); },
        [](const Case& c) {
            RigidBody a1 = c.body1;
            RigidBody a2 = c.body2;
            angular_impulse::resolve(a1, a2, c.contact);
            RigidBody e1 = c.body1;
            RigidBody e2 = c.body2;
            reference::resolve(e1, e2, c.contact);
            if (Verdict v = unchanged(c, a1, a2, {.velocity = true, .angular_velocity = true}, "resolve"); v.failed()) return v;
            // The scale of the answer: every point's speed before and after.
            double scale = 0.0;
            for (const RigidBody* b : {&c.body1, &c.body2, static_cast<const RigidBody*>(&e1), static_cast<const RigidBody*>(&e2)}) scale += length(b->velocity) + length(b->angular_velocity) * reach(c.contact, *b);
            // Each point that approached leaves at no less than -e u (the law, from the checker's input).
            const double e = combined_restitution(c.body1, c.body2);
            // Several points are one linear problem, often singular (a flat face's four points
            // move the body in three ways only): an exact solver rounds at its condition times
            // a few ulps; an iterative one (sweeps, each point's accumulated impulse clamped at
            // 0) converges slowly on a flat face, and after a fixed two thousand sweeps it is
            // still up to about 3e-5 of the speeds in play away. Every real mistake (one pass
            // over the points, a point that pulls, a missing angular term) is off by percents.
            const double tolerance = 1e-4 * scale;
            for (std::size_t i = 0; i < c.contact.point_count && !(c.body1.is_immovable() && c.body2.is_immovable()); ++i) {
                const Vector3 p = c.contact.points[i].position;
                const double u = point_normal_velocity(c, p, c.contact.normal);
                if (!(u < 0.0)) continue;
                const double after = dot(reference::point_velocity(a1, p) - reference::point_velocity(a2, p), c.contact.normal);
                const double reference_after = dot(reference::point_velocity(e1, p) - reference::point_velocity(e2, p), c.contact.normal);
                if (reference_after < -e * u - tolerance) continue;  // not a case the law decides (the reference's answer is the test)
                if (Verdict v = at_least(laws::every_point, "u' at point " + std::to_string(i + 1) + " after resolve", "m/s", -e * u, after,
                                         tolerance);
                    v.failed())
                    return v;
            }
            // An angular velocity is off by what moves a point at its lever arm by the tolerance.
            const BodyTolerance t1{tolerance, tolerance / std::max(lever(c.contact, c.body1), 1e-300)};
            const BodyTolerance t2{tolerance, tolerance / std::max(lever(c.contact, c.body2), 1e-300)};
            return compare_motion(c, a1, a2, e1, e2, t1, t2, laws::every_point, "resolve");
        },
        [](const Case& c) { return manifold_like(c); });
}
