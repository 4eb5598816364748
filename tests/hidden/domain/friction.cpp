// Chapter 6 over its whole legal domain (chapters/friction/friction.hpp): a thousand sampled
// legal inputs per function and step, each judged against the reference's answer computed
// here from the checker's own copy of the input (see sampling.hpp).
//
// Step 2 admits every right-handed orthonormal frame, so it is judged by its law alone, and
// step 5's answer is read in the frame of the student's own tangent_basis(). Step 5 grades
// the pass itself: its answer may match the reference's, or the pass the header writes down
// built from the student's own steps 1 to 4 (a mistake there costs its own step, not this one
// again). Either way the laws are computed from what the checker sent.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "../reference.hpp"
#include "../../steps/friction_laws.hpp"
#include "friction.hpp"
#include "sampling.hpp"

using namespace workbook;
using namespace workbook::domain;
namespace laws = workbook::friction_laws;
namespace reference = workbook::reference_friction;

namespace {

// ----- Drawing the header's domain ----------------------------------------------------------

/// A coefficient of friction: 0 (0.1), else 1e-6 to 10 log-uniformly, the ends on purpose.
double coefficient(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.1) return 0.0;
    if (pick < 0.15) return 1e-6;
    if (pick < 0.2) return 10.0;
    return decades(random, -6.0, 1.0);
}

/// A static coefficient for the dynamic one `mu_d`: the same (0.3), else larger, at most 10.
double static_for(SeededRandom& random, double mu_d) {
    if (chance(random, 0.3)) return mu_d;
    const double more = coefficient(random);
    return std::min(10.0, mu_d + more);
}

/// An inverse mass of the header's domain, 1e-6 to 1e6 kg: the ends on purpose (0.15).
double inverse_mass_6(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.075) return 1e-6;
    if (pick < 0.15) return 1e6;
    return decades(random, -6.0, 6.0);
}

/// A speed of the header's domain: 0 (0.1), else up to 1e3 (creeping ones among them).
double speed_3(SeededRandom& random) {
    if (chance(random, 0.1)) return 0.0;
    return decades(random, -9.0, 3.0);
}

Vector3 vector_3(SeededRandom& random) {
    const Vector3 d = random.direction();
    const double s = speed_3(random);
    return d * s;
}

/// A unit normal: an axis either way (0.2), next to one (0.2: 1e-12 to 1e-3 off it), or any.
Vector3 friction_normal(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.2) {
        const Vector3 axis = unit_normal(random);
        return nearest_axis(axis);
    }
    if (pick < 0.4) {
        const Vector3 axis = nearest_axis(random.direction());
        const Vector3 off = random.direction();
        const double by = decades(random, -12.0, -3.0);
        return normalized(axis + off * by);
    }
    return random.direction();
}

/// A body of the header's domain: movable with a mass of 1e-6 to 1e6 kg, or immovable (at rest
/// or a kinematic platform moving and spinning); coefficients drawn with their edges.
RigidBody friction_body(SeededRandom& random, double w, bool immovable) {
    RigidBody b = movable(random, w);
    b.position = position(random);
    b.velocity = vector_3(random);
    const Vector3 spin = vector_3(random);
    b.angular_velocity = spin / std::max(body_size(b), 1.0);
    if (immovable) {
        b.inverse_mass = 0.0;
        if (chance(random, 0.5)) b.inertia_body = Matrix3::zero();
        const bool moving = chance(random, 0.5);
        if (!moving) b.velocity = b.angular_velocity = Vector3{};
        b.update_world_inertia();
    }
    b.friction = coefficient(random);
    b.static_friction = static_for(random, b.friction);
    return b;
}

/// Two bodies of the domain: masses equal (0.1), at the two ends (0.1), or independent; body 2
/// immovable (0.35) or body 1 (0.1), never both.
void draw_bodies(SeededRandom& random, Case& c) {
    double w1 = inverse_mass_6(random);
    double w2 = inverse_mass_6(random);
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.1) w2 = w1;
    if (pick >= 0.1 && pick < 0.2) {
        w1 = 1e-6;
        w2 = 1e6;
        if (chance(random, 0.5)) std::swap(w1, w2);
    }
    const double pinned = random.uniform(0.0, 1.0);
    c.body1 = friction_body(random, w1, pinned >= 0.35 && pinned < 0.45);
    c.body2 = friction_body(random, w2, pinned < 0.35);
}

/// A contact on body 1 with 1 to 4 points: a ball's point on the normal through its centre
/// (0.35), a face's or an edge's corners across the normal below its centre (0.4), or points
/// near it anywhere (0.25); body 2 beyond the contact along the normal, its centre off to the side.
void draw_contact(SeededRandom& random, Case& c) {
    const Vector3 n = friction_normal(random);
    c.contact = Contact{};
    c.contact.normal = n;
    const RigidBody& anchor = c.body1.is_immovable() ? c.body2 : c.body1;
    const double size = body_size(anchor);
    const Vector3 centre = anchor.position;
    const double kind = random.uniform(0.0, 1.0);
    const double below = c.body1.is_immovable() ? 1.0 : -1.0;  // the contact lies below body 1, above body 2
    auto add = [&](const Vector3& p) {
        const double depth = chance(random, 0.3) ? 0.0 : decades(random, -6.0, -2.0);
        c.contact.add_point(p, depth);
    };
    if (kind < 0.35) {
        add(centre + n * (below * size));
    } else if (kind < 0.75) {
        const Vector3 t1 = normalized(cross(n, random.direction()));
        const Vector3 t2 = cross(n, t1);
        const double a = size * random.uniform(0.2, 1.0);
        const double b = size * random.uniform(0.2, 1.0);
        const double h = size * random.uniform(0.2, 1.0);
        const double shape = random.uniform(0.0, 1.0);
        const int count = shape < 0.4 ? 4 : shape < 0.7 ? 2 : 3;
        const double corners[4][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
        for (int i = 0; i < count; ++i) add(centre + n * (below * h) + t1 * (corners[i][0] * a) + t2 * (corners[i][1] * b));
    } else {
        const int count = 1 + int(random.uniform(0.0, 4.0));
        for (int i = 0; i < count; ++i) {
            const Vector3 d = random.direction();
            const double r = size * decades(random, -2.0, 0.5);
            add(centre + d * r);
        }
    }
    // The other body's centre: beyond the contact along the normal, often far to the side.
    RigidBody& other = c.body1.is_immovable() ? c.body1 : c.body2;
    const double other_size = body_size(other);
    const Vector3 side = cross(n, random.direction());
    const double away = chance(random, 0.4) ? decades(random, -2.0, 2.0) : 0.0;
    other.position = c.contact.points[0].position + n * (below * other_size * random.uniform(0.5, 2.0)) + side * away;
    other.update_world_inertia();
}

/// The solver's numbers at each point: an accumulated normal impulse (0 for a point that
/// touches without pushing or separates, 0.2), friction accumulated in earlier passes or
/// warm started (0, 0.4; else any components up to 1e3 kg m/s, often outside the cone), and
/// the other fields, which the pass must leave alone.
void draw_impulses(SeededRandom& random, Case& c) {
    c.impulses = ContactImpulses{};
    for (std::size_t i = 0; i < c.contact.point_count; ++i) {
        PointImpulse& p = c.impulses.points[i];
        p.normal = chance(random, 0.2) ? 0.0 : decades(random, -9.0, 3.0);
        if (!chance(random, 0.4)) {
            for (double& f : p.friction) {
                const double s = sign(random);
                const double size = chance(random, 0.1) ? 0.0 : decades(random, -9.0, 3.0);
                f = s * size;
            }
        }
        p.mass = random.uniform(0.0, 10.0);
        p.bounce = random.uniform(0.0, 1.0);
        p.bias = random.uniform(0.0, 1.0);
        p.pseudo = random.uniform(0.0, 1.0);
    }
}

/// Motions with their edges: no slip at all (0.15: equal velocities, no spin), a separating
/// pair (0.15: every point's normal impulse 0, moving apart), else as drawn.
void draw_motion(SeededRandom& random, Case& c) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.15) {
        const Vector3 v = vector_3(random);
        for (RigidBody* b : {&c.body1, &c.body2}) {
            b->velocity = v;
            b->angular_velocity = Vector3{};
        }
    } else if (pick < 0.3) {
        for (std::size_t i = 0; i < c.contact.point_count; ++i) c.impulses.points[i].normal = 0.0;
        RigidBody& mover = c.body1.is_immovable() ? c.body2 : c.body1;
        const double s = speed_3(random);
        mover.velocity += c.contact.normal * (c.body1.is_immovable() ? -s : s);
    }
}

bool draw_pass(SeededRandom& random, Case& c) {
    draw_bodies(random, c);
    draw_contact(random, c);
    draw_impulses(random, c);
    draw_motion(random, c);
    return true;
}

// ----- Tolerances ---------------------------------------------------------------------------

/// The longest lever arm of a contact's points about `b`'s centre, with the sizes of both
/// positions (what rounds in p - x).
double reach(const Contact& contact, const RigidBody& b) {
    double r = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const Vector3& p = contact.points[i].position;
        r = std::max(r, length(p - b.position) + length(p) + length(b.position));
    }
    return r;
}

/// The rounding of 1/k at `point` along `t`: k's terms, the inverse inertia amplified by its
/// condition, and then 1/k's own.
double mass_tolerance(const RigidBody& b1, const RigidBody& b2, const Vector3& point, const Vector3& t, double ulps = 64.0) {
    double scale = b1.inverse_mass + b2.inverse_mass;
    for (const RigidBody* b : {&b1, &b2}) {
        const double r = length(point - b->position) + length(point) + length(b->position);
        scale += inverse_reach(*b) * r * r;
    }
    const double k = 1.0 / reference::tangent_mass(b1, b2, point, t);
    return rounding(scale, ulps) / (k * k);
}

/// How far two right answers of one pass may lie apart.
struct PassTolerance {
    double friction = 0.0;  ///< each point's friction, kg m/s
    double v1 = 0.0, w1 = 0.0, v2 = 0.0, w2 = 0.0;
    double change = 0.0;  ///< the returned change of slip, m/s
};

/// The scale of a pass: J, every friction impulse it can hold or apply (at most the friction
/// before plus mu_s J_n at each point); V, every speed at the points, before and from J; M, the
/// largest effective mass. Each answer is a few thousand ulps of its scale (the points are
/// solved one after another, each from the last one's rounded answer).
PassTolerance pass_tolerance(const Case& c) {
    const double ulps = 4096.0;
    const double mu_s = reference::mix_coefficients(c.body1.static_friction, c.body2.static_friction);
    double j = 0.0;
    for (std::size_t i = 0; i < c.contact.point_count; ++i) {
        const PointImpulse& p = c.impulses.points[i];
        j += 2.0 * (std::hypot(p.friction[0], p.friction[1]) + mu_s * p.normal);
    }
    const double w = c.body1.inverse_mass + c.body2.inverse_mass;
    double v = 0.0;
    for (const RigidBody* b : {&c.body1, &c.body2}) {
        const double r = reach(c.contact, *b);
        v += length(b->velocity) + length(b->angular_velocity) * r + b->inverse_mass * j + inverse_reach(*b) * r * r * j;
    }
    const double m = w > 0.0 ? 1.0 / w : 0.0;
    PassTolerance t;
    t.friction = rounding(j + m * v, ulps);
    const double points = static_cast<double>(c.contact.point_count);
    const double r1 = reach(c.contact, c.body1);
    const double r2 = reach(c.contact, c.body2);
    t.v1 = rounding(length(c.body1.velocity) + c.body1.inverse_mass * j, ulps) + c.body1.inverse_mass * t.friction * points;
    t.v2 = rounding(length(c.body2.velocity) + c.body2.inverse_mass * j, ulps) + c.body2.inverse_mass * t.friction * points;
    t.w1 = rounding(length(c.body1.angular_velocity) + inverse_reach(c.body1) * r1 * j, ulps) + inverse_reach(c.body1) * r1 * t.friction * points;
    t.w2 = rounding(length(c.body2.angular_velocity) + inverse_reach(c.body2) * r2 * j, ulps) + inverse_reach(c.body2) * r2 * t.friction * points;
    t.change = rounding(v, ulps);
    return t;
}

// ----- The pass from parts ------------------------------------------------------------------

/// What a pass returns and leaves.
struct PassAnswer {
    RigidBody body1;
    RigidBody body2;
    ContactImpulses impulses;
    double change = 0.0;
    std::array<Vector3, 2> tangents{};
};

Vector3 point_velocity(const RigidBody& b, const Vector3& p) { return b.velocity + cross(b.angular_velocity, p - b.position); }

// The student's own parts, each in place of the reference's where it has been written: an
// unfinished part (one that returns 0 or does nothing where the reference does something) is
// replaced by the reference's, so that a pass that does nothing never matches a pass built from
// parts that do nothing.

double own_mix(double mu1, double mu2) {
    const double mixed = friction::mix_coefficients(mu1, mu2);
    return mu1 > 0.0 && mu2 > 0.0 && !(mixed > 0.0) ? reference::mix_coefficients(mu1, mu2) : mixed;
}

std::array<Vector3, 2> own_basis(const Vector3& normal) {
    const std::array<Vector3, 2> t = friction::tangent_basis(normal);
    return length(t[0]) > 0.0 || length(t[1]) > 0.0 ? t : reference::tangent_basis(normal);
}

double own_tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& tangent) {
    const double mass = friction::tangent_mass(body1, body2, point, tangent);
    return mass == 0.0 ? reference::tangent_mass(body1, body2, point, tangent) : mass;
}

std::array<double, 2> own_accumulate(std::array<double, 2>& accumulated, const std::array<double, 2>& increment, double normal_impulse,
                                     double mu_s, double mu_d) {
    std::array<double, 2> sum = accumulated;
    const std::array<double, 2> applied = friction::accumulate_friction(sum, increment, normal_impulse, mu_s, mu_d);
    const bool inert = sum == accumulated && applied == std::array<double, 2>{};
    if (!inert) {
        accumulated = sum;
        return applied;
    }
    return reference::accumulate_friction(accumulated, increment, normal_impulse, mu_s, mu_d);
}

/// The pass as the header writes it down, from the student's own steps 1 to 4, on the checker's
/// copy of the input; its slip and its impulse at each point are the laws' own formulas.
PassAnswer pass_from_students_parts(const Case& c) {
    PassAnswer a{c.body1, c.body2, c.impulses, 0.0, own_basis(c.contact.normal)};
    const double mu_s = own_mix(c.body1.static_friction, c.body2.static_friction);
    const double mu_d = own_mix(c.body1.friction, c.body2.friction);
    for (std::size_t i = 0; i < c.contact.point_count; ++i) {
        PointImpulse& p = a.impulses.points[i];
        const Vector3& at = c.contact.points[i].position;
        const Vector3 slip = point_velocity(a.body1, at) - point_velocity(a.body2, at);
        std::array<double, 2> increment{};
        for (std::size_t d = 0; d < 2; ++d) increment[d] = -own_tangent_mass(a.body1, a.body2, at, a.tangents[d]) * dot(slip, a.tangents[d]);
        const std::array<double, 2> applied = own_accumulate(p.friction, increment, p.normal, mu_s, mu_d);
        const Vector3 j = applied[0] * a.tangents[0] + applied[1] * a.tangents[1];
        if (j == Vector3{}) continue;
        a.body1.velocity += a.body1.inverse_mass * j;
        a.body1.angular_velocity += a.body1.inverse_inertia_world * cross(at - a.body1.position, j);
        a.body2.velocity -= a.body2.inverse_mass * j;
        a.body2.angular_velocity -= a.body2.inverse_inertia_world * cross(at - a.body2.position, j);
        const Vector3 change = point_velocity(a.body1, at) - point_velocity(a.body2, at) - slip;
        a.change = std::max(a.change, length(change - dot(change, c.contact.normal) * c.contact.normal));
    }
    return a;
}

Vector3 friction_vector(const PointImpulse& p, const std::array<Vector3, 2>& t) { return p.friction[0] * t[0] + p.friction[1] * t[1]; }

bool answer_finite(const PassAnswer& a) {
    bool finite = is_finite(a.body1.velocity) && is_finite(a.body1.angular_velocity) && is_finite(a.body2.velocity) &&
                  is_finite(a.body2.angular_velocity) && std::isfinite(a.change) && is_finite(a.tangents[0]) && is_finite(a.tangents[1]);
    for (const PointImpulse& p : a.impulses.points) finite = finite && std::isfinite(p.friction[0]) && std::isfinite(p.friction[1]);
    return finite;
}

/// The student's answer against one right answer: each point's friction as a vector (the
/// student's read in the student's tangents, the expected one in its own), then the bodies,
/// then the returned change. A point's friction is judged by the law of its case: no push, a
/// point that sticks (its slip stopped), or one on the rim of the cone.
Verdict compare_pass(const Case& c, const PassAnswer& actual, const PassAnswer& expected, const PassTolerance& t) {
    const double mu_s = reference::mix_coefficients(c.body1.static_friction, c.body2.static_friction);
    for (std::size_t i = 0; i < c.contact.point_count; ++i) {
        const Vector3 want = friction_vector(expected.impulses.points[i], expected.tangents);
        const Vector3 is = friction_vector(actual.impulses.points[i], actual.tangents);
        const double normal = c.impulses.points[i].normal;
        const bool sticks = length(want) < mu_s * normal * (1.0 - 1e-9);
        const Law& law = normal == 0.0 ? laws::no_push : sticks ? laws::slip_stops : laws::pass_cone;
        if (Verdict v = compare(law, "point " + std::to_string(i + 1) + "'s friction, friction[0] t1 + friction[1] t2, after solve_friction",
                                "kg m/s", want, is, t.friction);
            v.failed())
            return v;
    }
    for (int side = 1; side <= 2; ++side) {
        const RigidBody& was = side == 1 ? c.body1 : c.body2;
        const RigidBody& is = side == 1 ? actual.body1 : actual.body2;
        const RigidBody& want = side == 1 ? expected.body1 : expected.body2;
        const std::string who = "body " + std::to_string(side) + "'s ";
        if (was.is_immovable()) {
            if (Verdict v = compare(laws::pass_apply, "the immovable " + who + "velocity after solve_friction", "m/s", was.velocity, is.velocity, 0.0);
                v.failed())
                return v;
            if (Verdict v = compare(laws::pass_apply, "the immovable " + who + "angular velocity after solve_friction", "rad/s",
                                    was.angular_velocity, is.angular_velocity, 0.0);
                v.failed())
                return v;
            continue;
        }
        if (Verdict v = compare(laws::pass_apply, who + "velocity after solve_friction", "m/s", want.velocity, is.velocity, side == 1 ? t.v1 : t.v2);
            v.failed())
            return v;
        if (Verdict v = compare(laws::pass_apply, who + "angular velocity after solve_friction", "rad/s", want.angular_velocity,
                                is.angular_velocity, side == 1 ? t.w1 : t.w2);
            v.failed())
            return v;
    }
    return compare(laws::pass_change, "the change of slip solve_friction returns", "m/s", expected.change, actual.change, t.change);
}

/// Every field of the points' impulses but `friction` (and every field of the points the
/// contact does not have) back exactly as sent.
Verdict impulses_unchanged(const Case& c, const ContactImpulses& after) {
    for (std::size_t i = 0; i < max_contact_points; ++i) {
        const PointImpulse& a = c.impulses.points[i];
        const PointImpulse& b = after.points[i];
        const std::string who = "impulses.points[" + std::to_string(i) + "].";
        const std::array<std::pair<const char*, std::pair<double, double>>, 5> fields{
            {{"mass", {a.mass, b.mass}}, {"bounce", {a.bounce, b.bounce}}, {"bias", {a.bias, b.bias}}, {"normal", {a.normal, b.normal}},
             {"pseudo", {a.pseudo, b.pseudo}}}};
        for (const auto& [name, values] : fields)
            if (!same(values.first, values.second))
                return compare(unchanged_law, who + name + " after solve_friction", "", values.first, values.second, 0.0);
        if (i >= c.contact.point_count)
            for (std::size_t d = 0; d < 2; ++d)
                if (!same(a.friction[d], b.friction[d]))
                    return compare(unchanged_law, who + "friction[" + std::to_string(d) + "] of a point the contact does not have", "",
                                   a.friction[d], b.friction[d], 0.0);
    }
    return {};
}

Verdict judge_pass(const Case& c) {
    PassAnswer actual{c.body1, c.body2, c.impulses, 0.0, {}};
    actual.change = friction::solve_friction(actual.body1, actual.body2, c.contact, actual.impulses);
    actual.tangents = friction::tangent_basis(c.contact.normal);
    if (Verdict v = unchanged(c, actual.body1, actual.body2, {.velocity = true, .angular_velocity = true}, "solve_friction"); v.failed()) return v;
    if (Verdict v = impulses_unchanged(c, actual.impulses); v.failed()) return v;
    PassAnswer expected{c.body1, c.body2, c.impulses, 0.0, reference::tangent_basis(c.contact.normal)};
    expected.change = reference::solve_friction(expected.body1, expected.body2, c.contact, expected.impulses);
    const PassTolerance t = pass_tolerance(c);
    const Verdict against_reference = compare_pass(c, actual, expected, t);
    if (!against_reference.failed()) return {};
    const PassAnswer own = pass_from_students_parts(c);
    if (answer_finite(own) && !compare_pass(c, actual, own, t).failed()) return {};
    return against_reference;
}

// ----- Steps 1 to 4 -------------------------------------------------------------------------

/// A unit tangent of a unit normal, at any angle about it.
Vector3 draw_tangent(SeededRandom& random, const Vector3& normal) {
    const std::array<Vector3, 2> t = reference::tangent_basis(normal);
    const double angle = random.uniform(0.0, 6.283185307179586);
    return t[0] * std::cos(angle) + t[1] * std::sin(angle);
}

/// A friction component: 0 (0.15), else up to 1e3 kg m/s either way.
double component(SeededRandom& random) {
    if (chance(random, 0.15)) return 0.0;
    const double s = sign(random);
    const double size = decades(random, -9.0, 3.0);
    return s * size;
}

Verdict judge_accumulate(const Case& c) {
    std::array<double, 2> sum = c.accumulated;
    const std::array<double, 2> applied =
        friction::accumulate_friction(sum, c.increment, c.normal_impulse, c.static_coefficient, c.dynamic_coefficient);
    std::array<double, 2> expected_sum = c.accumulated;
    (void)reference::accumulate_friction(expected_sum, c.increment, c.normal_impulse, c.static_coefficient, c.dynamic_coefficient);
    const std::array<double, 2> raw{c.accumulated[0] + c.increment[0], c.accumulated[1] + c.increment[1]};
    const double size = std::hypot(raw[0], raw[1]);
    const double limit = c.static_coefficient * c.normal_impulse;
    const double tolerance = rounding(std::hypot(c.accumulated[0], c.accumulated[1]) + std::hypot(c.increment[0], c.increment[1]) + limit);
    const bool sticks = size <= limit;
    const Law& law = c.normal_impulse == 0.0 ? laws::no_push : sticks ? laws::stick : laws::slide;
    auto judge = [&](const std::array<double, 2>& want) -> Verdict {
        for (std::size_t d = 0; d < 2; ++d) {
            const std::string which = d == 0 ? "first" : "second";
            if (Verdict v = compare(law, "the new sum's " + which + " component", "kg m/s", want[d] + 0.0, sum[d], tolerance); v.failed()) return v;
            if (Verdict v = compare(law, "the returned change's " + which + " component", "kg m/s", want[d] - c.accumulated[d], applied[d], tolerance);
                v.failed())
                return v;
        }
        return {};
    };
    const Verdict v = judge(expected_sum);
    if (!v.failed()) return v;
    // On the rim of the static cone (to rounding) either answer is right: sticking, or sliding.
    if (std::abs(size - limit) <= tolerance && size > 0.0) {
        const double scale = sticks ? c.dynamic_coefficient * c.normal_impulse / size : 1.0;
        if (!judge({raw[0] * scale, raw[1] * scale}).failed()) return {};
    }
    return v;
}

}  // namespace

TEST_CASE("sampled coefficients from a millionth to ten, zeros and equal pairs among them: the mix",
          "[friction][step:1:mix-coefficients][points:3]") {
    sample(
        601, {.body1 = false, .body2 = false, .mix = true},
        [](SeededRandom& random, Case& c) {
            c.mu1 = coefficient(random);
            const bool equal = chance(random, 0.2);
            c.mu2 = equal ? c.mu1 : coefficient(random);
            return true;
        },
        [](const Case& c) {
            const double expected = reference::mix_coefficients(c.mu1, c.mu2);
            return compare(laws::mix, "mix_coefficients", "", expected, friction::mix_coefficients(c.mu1, c.mu2), rounding(expected, 16.0));
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled unit normals, along the axes, a hair off them and any way: a right-handed orthonormal frame",
          "[friction][step:2:tangent-basis][points:3]") {
    sample(
        602, {.body1 = false, .body2 = false, .normal = true},
        [](SeededRandom& random, Case& c) {
            c.normal = friction_normal(random);
            return true;
        },
        [](const Case& c) {
            const Vector3 n = c.normal;
            const std::array<Vector3, 2> t = friction::tangent_basis(n);
            const double tolerance = rounding(1.0, 32.0);
            struct Check {
                const char* what;
                double expected, actual;
            };
            for (const Check& k : {Check{"|t1|", 1.0, length(t[0])}, Check{"|t2|", 1.0, length(t[1])}, Check{"t1 . n", 0.0, dot(t[0], n)},
                                   Check{"t2 . n", 0.0, dot(t[1], n)}, Check{"t1 . t2", 0.0, dot(t[0], t[1])}})
                if (Verdict v = compare(laws::frame, k.what, "", k.expected, k.actual, tolerance); v.failed()) return v;
            if (Verdict v = compare(laws::frame, "t1 x t2, which must be n", "", n, cross(t[0], t[1]), tolerance); v.failed()) return v;
            const std::array<Vector3, 2> again = friction::tangent_basis(n);
            if (Verdict v = compare(laws::frame, "t1 of a second call", "", t[0], again[0], 0.0); v.failed()) return v;
            return compare(laws::frame, "t2 of a second call", "", t[1], again[1], 0.0);
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled pairs, kinematic platforms and extreme masses among them, points anywhere near: the tangential mass",
          "[friction][step:3:tangent-mass][points:3]") {
    sample(
        603, {.point = true, .spin = true, .tangent = true},
        [](SeededRandom& random, Case& c) {
            draw_bodies(random, c);
            draw_contact(random, c);
            c.point = c.contact.points[0].position;
            c.tangent = draw_tangent(random, c.contact.normal);
            return true;
        },
        [](const Case& c) {
            const Vector3 p = c.point;
            const double expected = reference::tangent_mass(c.body1, c.body2, p, c.tangent);
            const double actual = friction::tangent_mass(c.body1, c.body2, p, c.tangent);
            return compare(laws::tangent_mass, "tangent_mass at the point along the tangent", "kg", expected, actual,
                           mass_tolerance(c.body1, c.body2, p, c.tangent));
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled sums inside, on and far outside the cone, zero normal impulses and ice among them: accumulate_friction",
          "[friction][step:4:accumulate-friction][points:3]") {
    sample(
        604, {.body1 = false, .body2 = false, .accumulate = true},
        [](SeededRandom& random, Case& c) {
            const bool fresh = chance(random, 0.3);
            for (double& a : c.accumulated) a = fresh ? 0.0 : component(random);
            const double kind = random.uniform(0.0, 1.0);
            if (kind < 0.1) {
                c.increment = {-c.accumulated[0], -c.accumulated[1]};  // the sum is exactly 0
            } else if (kind < 0.2) {
                c.increment = {0.0, 0.0};
            } else {
                for (double& i : c.increment) i = component(random);
            }
            c.normal_impulse = chance(random, 0.2) ? 0.0 : decades(random, -9.0, 3.0);
            c.dynamic_coefficient = coefficient(random);
            c.static_coefficient = static_for(random, c.dynamic_coefficient);
            return true;
        },
        [](const Case& c) { return judge_accumulate(c); }, [](const Case&) { return true; });
}

TEST_CASE("sampled contacts of 1 to 4 points between spinning bodies, immovable and kinematic ones, no slip, no push and "
          "separating ones among them: one friction pass",
          "[friction][step:5:solve-friction][points:4]") {
    sample(
        605, {.contact = true, .spin = true, .impulses = true}, [](SeededRandom& random, Case& c) { return draw_pass(random, c); },
        [](const Case& c) { return judge_pass(c); },
        [](const Case& c) { return c.contact.point_count >= 1 && !(c.body1.is_immovable() && c.body2.is_immovable()); });
}
