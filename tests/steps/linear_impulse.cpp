// Public step tests for chapter 3, linear impulses with restitution.
// Tags: [linear-impulse] chapter, [step:N:name] the step a test grades, [points:P] its weight.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <string>

#include "feedback.hpp"
#include "sent_values.hpp"
#include "linear-impulse.hpp"
#include "linear_impulse_laws.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
namespace laws = workbook::linear_impulse_laws;
using workbook::testing::describe;
using workbook::testing::expect_at_least;
using workbook::testing::expect_close;
using workbook::testing::rounding_tolerance;

namespace {

RigidBody ball(double mass, double restitution, Vector3 position, Vector3 velocity) {
    RigidBody body = make_sphere(mass, 0.5, position, velocity);
    body.restitution = restitution;
    return body;
}

/// A contact whose normal points from body 2 to body 1, as detection reports it.
Contact contact_between(const RigidBody& body1, const RigidBody& body2) {
    Contact c;
    c.normal = normalized(body1.position - body2.position);
    c.add_point((body1.position + body2.position) / 2.0, 0.01);
    return c;
}

std::string pair_text(const RigidBody& a, const RigidBody& b) {
    return "body 1: " + describe(a) + ", e = " + workbook::testing::format(a.restitution) + "; body 2: " + describe(b) +
           ", e = " + workbook::testing::format(b.restitution);
}

Vector3 momentum(const RigidBody& a, const RigidBody& b) { return a.mass() * a.velocity + b.mass() * b.velocity; }

double momentum_scale(const RigidBody& a, const RigidBody& b) {
    return a.mass() * length(a.velocity) + b.mass() * length(b.velocity);
}

/// 1/2 m |v - frame|^2, and 0 for an immovable body.
double kinetic_energy_in_frame(const RigidBody& body, const Vector3& frame) {
    return body.is_immovable() ? 0.0 : 0.5 * body.mass() * length_squared(body.velocity - frame);
}

Vector3 tangential(const Vector3& v, const Vector3& unit_normal) { return v - dot(v, unit_normal) * unit_normal; }

/// Resolves the pair and checks every law of a whole response: momentum (between movable
/// bodies), restitution along n, the tangential part, and the energy lost.
void expect_full_response(RigidBody body1, RigidBody body2, const std::string& name) {
    const Contact contact = contact_between(body1, body2);
    const Vector3 n = contact.normal;
    const RigidBody before1 = body1;
    const RigidBody before2 = body2;
    const std::string situation = name + ": " + pair_text(body1, body2) + ", normal " + workbook::testing::format(n);
    const double e = combined_restitution(body1, body2);
    const Vector3 v12 = body1.velocity - body2.velocity;
    const double speed = length(body1.velocity) + length(body2.velocity);
    linear_impulse::resolve(body1, body2, contact);
    const Vector3 v12_after = body1.velocity - body2.velocity;
    // Momentum and the immovable bodies first: the first failure is the one a student reads, and
    // an impulse of the same sign on both bodies, or one without its inverse mass, breaks
    // momentum before anything else (restitution then fails only as a consequence).
    if (!before1.is_immovable() && !before2.is_immovable()) {
        expect_close(laws::momentum, momentum(before1, before2), momentum(testing::judged(before1, body1), testing::judged(before2, body2)),
                     rounding_tolerance(momentum_scale(before1, before2), 32), "kg m/s", situation + " (total momentum after)");
    }
    if (before1.is_immovable()) {
        expect_close(laws::immovable, before1.velocity, body1.velocity, 0.0, "m/s", situation + " (body 1 after)");
    }
    if (before2.is_immovable()) {
        expect_close(laws::immovable, before2.velocity, body2.velocity, 0.0, "m/s", situation + " (body 2 after)");
    }
    expect_close(laws::restitution, -e * dot(v12, n), dot(v12_after, n), rounding_tolerance(speed, 32), "m/s",
                 situation + " (v12' . n after)");
    expect_close(laws::tangential, tangential(v12, n), tangential(v12_after, n), rounding_tolerance(speed, 32), "m/s",
                 situation + " (tangential relative velocity after)");
    const double mu = 1.0 / (before1.inverse_mass + before2.inverse_mass);
    const double vn = dot(v12, n);
    // Measured in the frame of an immovable body (a moving platform does work in any other frame).
    const Vector3 frame = before1.is_immovable() ? before1.velocity : before2.is_immovable() ? before2.velocity : Vector3{};
    const double energy_before = kinetic_energy_in_frame(before1, frame) + kinetic_energy_in_frame(before2, frame);
    const double energy_after =
        kinetic_energy_in_frame(testing::judged(before1, body1), frame) + kinetic_energy_in_frame(testing::judged(before2, body2), frame);
    expect_close(laws::energy, 0.5 * mu * (1.0 - e * e) * vn * vn, energy_before - energy_after,
                 rounding_tolerance(energy_before + energy_after, 64), "J", situation + " (kinetic energy lost)");
}

}  // namespace

// ----- Step 1 -----------------------------------------------------------------------------

TEST_CASE("relative normal velocity of a 2 kg cart at 3 m/s and a 1 kg cart at rest",
          "[linear-impulse][step:1:relative-normal-velocity][points:2]") {
    // Cart 1 comes from the left, so the normal from cart 2 to cart 1 points along -x.
    const RigidBody cart1 = ball(2.0, 0.5, {-0.95, 0, 0}, {3, 0, 0});
    const RigidBody cart2 = ball(1.0, 0.5, {0, 0, 0}, {0, 0, 0});
    const Vector3 n = contact_between(cart1, cart2).normal;
    expect_close(laws::normal_velocity, -3.0, linear_impulse::relative_normal_velocity(cart1, cart2, n), rounding_tolerance(3.0),
                 "m/s", pair_text(cart1, cart2) + ", normal " + workbook::testing::format(n));
}

TEST_CASE("relative normal velocity in 3D, approaching and separating", "[linear-impulse][step:1:relative-normal-velocity][points:2]") {
    const RigidBody body1 = ball(0.5, 1.0, {0, 0, 0}, {1, -2, 0.5});
    const RigidBody body2 = ball(3.0, 1.0, {0.6, 0.8, 0}, {-1, 1, 2});
    const Vector3 n = contact_between(body1, body2).normal;  // (-0.6, -0.8, 0)
    // v12 = (2, -3, -1.5): 2 * -0.6 + -3 * -0.8 = 1.2, separating along this normal.
    const std::string situation = pair_text(body1, body2) + ", normal " + workbook::testing::format(n);
    expect_close(laws::normal_velocity, 1.2, linear_impulse::relative_normal_velocity(body1, body2, n), rounding_tolerance(4.0),
                 "m/s", situation);
    expect_close(laws::normal_velocity, 1.2, linear_impulse::relative_normal_velocity(body2, body1, -n), rounding_tolerance(4.0),
                 "m/s", situation + " (bodies swapped, normal reversed: the same contact, the same sign)");
    expect_close(laws::normal_velocity, -1.2, linear_impulse::relative_normal_velocity(body1, body2, -n), rounding_tolerance(4.0),
                 "m/s", situation + " (normal reversed: approaching)");
}

// ----- Step 2 -----------------------------------------------------------------------------

TEST_CASE("a pair moving apart is left alone, its mirror image is not", "[linear-impulse][step:2:separating-contacts][points:2]") {
    RigidBody left = ball(1.0, 0.5, {-0.45, 0, 0}, {-2, 0, 0});
    RigidBody right = ball(1.0, 0.5, {0.45, 0, 0}, {1, 0, 0});
    const std::string apart = pair_text(right, left);
    linear_impulse::resolve(right, left, contact_between(right, left));
    expect_close(laws::separating, Vector3{1, 0, 0}, right.velocity, 0.0, "m/s", apart + " (moving apart: body 1 after)");
    expect_close(laws::separating, Vector3{-2, 0, 0}, left.velocity, 0.0, "m/s", apart + " (moving apart: body 2 after)");

    left.velocity = {2, 0, 0};
    right.velocity = {-1, 0, 0};
    const std::string towards = pair_text(right, left);
    linear_impulse::resolve(right, left, contact_between(right, left));
    // Any change passes here; how much is step 4's business, so that one mistake is reported once.
    const double change = length(right.velocity - Vector3{-1, 0, 0}) + length(left.velocity - Vector3{2, 0, 0});
    expect_at_least(laws::respond, 1e-6 * 3.0, change, 0.0, "m/s",
                    towards + " (approaching: |v1' - v1| + |v2' - v2|, how much resolve changed the velocities)");
}

TEST_CASE("a sliding contact and a resting contact get no impulse", "[linear-impulse][step:2:separating-contacts][points:2]") {
    // A ball sliding along a wall: v12 . n = 0 exactly.
    RigidBody slider = ball(2.0, 1.0, {0, 0.5, 0}, {3, 0, -1});
    RigidBody wall = make_immovable_sphere(1.0, {0, -1.0, 0});
    std::string situation = pair_text(slider, wall);
    linear_impulse::resolve(slider, wall, contact_between(slider, wall));
    expect_close(laws::separating, Vector3{3, 0, -1}, slider.velocity, 0.0, "m/s", situation + " (sliding: body 1 after)");
    // Two balls touching with the same velocity.
    RigidBody a = ball(1.0, 0.5, {0, 0, 0}, {0.5, -2, 1});
    RigidBody b = ball(4.0, 0.5, {0.3, 0.4, 0.8}, {0.5, -2, 1});
    situation = pair_text(a, b);
    linear_impulse::resolve(a, b, contact_between(a, b));
    expect_close(laws::separating, Vector3{0.5, -2, 1}, a.velocity, 0.0, "m/s", situation + " (equal velocities: body 1 after)");
    expect_close(laws::separating, Vector3{0.5, -2, 1}, b.velocity, 0.0, "m/s", situation + " (equal velocities: body 2 after)");
    // And one that does approach must still be resolved.
    RigidBody faller = ball(2.0, 0.5, {0, 0.5, 0}, {3, -1, 0});
    situation = pair_text(faller, wall);
    const Vector3 wall_velocity = wall.velocity;
    linear_impulse::resolve(faller, wall, contact_between(faller, wall));
    // Both bodies: whether resolve responds is this step's question; which body gets how much
    // (an impulse given to the wall instead, say) is step 4's, so that one mistake costs one step.
    expect_at_least(laws::respond, 1e-6, length(faller.velocity - Vector3{3, -1, 0}) + length(wall.velocity - wall_velocity), 0.0, "m/s",
                    situation + " (approaching: |v1' - v1| + |v2' - v2|, how much resolve changed the velocities)");
}

// ----- Step 3 -----------------------------------------------------------------------------

TEST_CASE("impulse of the worked example: 2 kg at 3 m/s into 1 kg at rest, e = 0.5", "[linear-impulse][step:3:impulse-size][points:2]") {
    const RigidBody cart1 = ball(2.0, 0.5, {-0.95, 0, 0}, {3, 0, 0});
    const RigidBody cart2 = ball(1.0, 0.5, {0, 0, 0}, {0, 0, 0});
    const Vector3 n = contact_between(cart1, cart2).normal;
    const std::string situation = pair_text(cart1, cart2) + ", normal " + workbook::testing::format(n);
    // J = -(1 + 0.5)(-3) / (1 * (0.5 + 1)) = 3 N s
    expect_close(laws::impulse, 3.0, linear_impulse::impulse_magnitude(cart1, cart2, n, 0.5), rounding_tolerance(3.0), "N s",
                 situation + ", restitution argument 0.5");
    expect_close(laws::impulse, 2.0, linear_impulse::impulse_magnitude(cart1, cart2, n, 0.0), rounding_tolerance(3.0), "N s",
                 situation + ", restitution argument 0");
    expect_close(laws::impulse, 4.0, linear_impulse::impulse_magnitude(cart1, cart2, n, 1.0), rounding_tolerance(3.0), "N s",
                 situation + ", restitution argument 1");
}

TEST_CASE("against an immovable wall J = (1 + e) m |v . n|, and two walls give 0", "[linear-impulse][step:3:impulse-size][points:2]") {
    const RigidBody ball1 = ball(2.0, 0.8, {0, 0, 0}, {-3, 1, 0});
    const RigidBody wall = make_immovable_sphere(1.0, {-1.4, 0, 0});
    const Vector3 n = contact_between(ball1, wall).normal;  // (1, 0, 0)
    std::string situation = pair_text(ball1, wall) + ", normal " + workbook::testing::format(n) + ", restitution argument 0.8";
    const double j = linear_impulse::impulse_magnitude(ball1, wall, n, 0.8);
    expect_at_least(laws::push, 0.0, j, 0.0, "N s", situation);
    expect_close(laws::impulse, 1.8 * 3.0 * 2.0, j, rounding_tolerance(10.8), "N s", situation);
    // The same contact with the wall as body 1: the normal flips, J does not.
    expect_close(laws::impulse, 1.8 * 3.0 * 2.0, linear_impulse::impulse_magnitude(wall, ball1, -n, 0.8), rounding_tolerance(10.8),
                 "N s", situation + " (the wall as body 1, normal reversed)");
    const RigidBody wall2 = make_immovable_sphere(1.0, {1.5, 0, 0});
    RigidBody moving_wall = make_immovable_sphere(1.0, {0, 0, 0});
    moving_wall.velocity = {1, 0, 0};
    situation = "two immovable bodies approaching: " + pair_text(moving_wall, wall2);
    expect_close(laws::immovable, 0.0, linear_impulse::impulse_magnitude(moving_wall, wall2, {-1, 0, 0}, 1.0), 0.0, "N s", situation);
}

TEST_CASE("a normal of any length gives the same impulse J n", "[linear-impulse][step:3:impulse-size][points:2]") {
    const RigidBody body1 = ball(0.25, 1.0, {0, 0, 0}, {4, -1, 2});
    const RigidBody body2 = ball(3.0, 1.0, {0.48, 0.6, 0.64}, {-1, 2, 0.5});
    const Vector3 unit = contact_between(body1, body2).normal;
    // v12 . n = -1.56 m/s, w1 + w2 = 4 + 1/3 per kg: J = 1.7 * 1.56 / (13/3) N s.
    const double expected = 1.7 * 1.56 * 3.0 / 13.0;
    expect_close(laws::impulse, expected, linear_impulse::impulse_magnitude(body1, body2, unit, 0.7), rounding_tolerance(expected, 32),
                 "N s", pair_text(body1, body2) + ", restitution argument 0.7, unit normal " + workbook::testing::format(unit));
    const Vector3 reference_impulse = expected * unit;
    for (const double k : {2.5, 0.1}) {
        const Vector3 n = k * unit;
        const std::string situation = pair_text(body1, body2) + ", restitution argument 0.7, normal " + workbook::testing::format(n) +
                                      " (length " + workbook::testing::format(k) + ")";
        expect_close(laws::normal_length, reference_impulse, linear_impulse::impulse_magnitude(body1, body2, n, 0.7) * n,
                     rounding_tolerance(length(reference_impulse), 32), "N s", situation + ": the impulse vector J n");
    }
}

// ----- Step 4 -----------------------------------------------------------------------------

TEST_CASE("head-on carts bounce with e = 0.5: 1.5 m/s and 3 m/s", "[linear-impulse][step:4:apply-impulse][points:2]") {
    RigidBody cart1 = ball(2.0, 0.5, {-0.95, 0, 0}, {3, 0, 0});
    RigidBody cart2 = ball(1.0, 0.5, {0, 0, 0}, {0, 0, 0});
    const std::string situation = pair_text(cart1, cart2);
    const Vector3 p = momentum(cart1, cart2);
    linear_impulse::resolve(cart1, cart2, contact_between(cart1, cart2));
    expect_close(laws::momentum, p, momentum(cart1, cart2), rounding_tolerance(6.0), "kg m/s", situation + " (total momentum after)");
    expect_close(laws::restitution, Vector3{1.5, 0, 0}, cart1.velocity, rounding_tolerance(3.0), "m/s", situation + " (cart 1 after)");
    expect_close(laws::restitution, Vector3{3, 0, 0}, cart2.velocity, rounding_tolerance(3.0), "m/s", situation + " (cart 2 after)");
    expect_full_response(ball(2.0, 0.5, {-0.95, 0, 0}, {3, 0, 0}), ball(1.0, 0.5, {0, 0, 0}, {0, 0, 0}), "head-on carts");
}

TEST_CASE("an oblique hit in 3D: the normal part bounces, the tangential part is kept", "[linear-impulse][step:4:apply-impulse][points:2]") {
    // e = 0.8 and 0.6 combine to the smaller, 0.6.
    expect_full_response(ball(1.5, 0.8, {0, 0, 0}, {4, -1, 2}), ball(0.5, 0.6, {0.48, 0.6, 0.64}, {-1, 2, -0.5}), "oblique hit");
}

TEST_CASE("an immovable wall on either side, and a moving platform, keep their velocities", "[linear-impulse][step:4:apply-impulse][points:2]") {
    RigidBody wall = make_immovable_sphere(1.0, {-1.4, 0, 0});
    expect_full_response(ball(2.0, 0.8, {0, 0, 0}, {-3, 1, 0}), wall, "a ball into a wall (body 2)");
    expect_full_response(wall, ball(2.0, 0.8, {0, 0, 0}, {-3, 1, 0}), "a ball into a wall (body 1)");
    RigidBody platform = make_immovable_sphere(1.0, {0, 0, 0});
    platform.velocity = {0, 1.5, 0};
    expect_full_response(ball(5.0, 1.0, {0.3, 1.4, 0}, {0, -2, 0.5}), platform, "a ball onto a rising platform");
}

TEST_CASE("a contact with four points still gets one impulse", "[linear-impulse][step:4:apply-impulse][points:2]") {
    // A box face lying on another reports four points; the linear impulse does not depend on them.
    RigidBody top = ball(2.0, 1.0, {0, 0.5, 0}, {0.5, -2, 0});
    RigidBody bottom = ball(6.0, 1.0, {0, -0.5, 0}, {0, 1, 0});
    Contact contact;
    contact.normal = {0, 1, 0};
    for (const double x : {-0.2, 0.2})
        for (const double z : {-0.2, 0.2}) contact.add_point({x, 0, z}, 0.01);
    const std::string situation = pair_text(top, bottom) + ", a contact with 4 points";
    const Vector3 p = momentum(top, bottom);
    const RigidBody top_sent = top;
    const RigidBody bottom_sent = bottom;
    linear_impulse::resolve(top, bottom, contact);
    expect_close(laws::momentum, p, momentum(testing::judged(top_sent, top), testing::judged(bottom_sent, bottom)), rounding_tolerance(12.0), "kg m/s", situation + " (total momentum after)");
    // v12 . n = -3, e = 1: v12' . n = +3; mu = 1.5 kg, J = 9 N s: top 0.5 -> 2.5, bottom 1 -> -0.5.
    expect_close(laws::restitution, Vector3{0.5, 2.5, 0}, top.velocity, rounding_tolerance(3.0), "m/s", situation + " (body 1 after)");
    expect_close(laws::restitution, Vector3{0, -0.5, 0}, bottom.velocity, rounding_tolerance(3.0), "m/s", situation + " (body 2 after)");
}
