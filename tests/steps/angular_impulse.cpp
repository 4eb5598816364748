// Public step tests for chapter 4, angular impulses.
// Tags: [angular-impulse] chapter, [step:N:name] the step a test grades, [points:P] its weight.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <numbers>

#include "angular-impulse.hpp"
#include "angular_impulse_bodies.hpp"
#include "angular_impulse_laws.hpp"
#include "feedback.hpp"
#include "sent_values.hpp"
#include "seeded_random.hpp"

using namespace workbook;
using namespace workbook::angular_impulse_cases;
namespace laws = workbook::angular_impulse_laws;
using workbook::testing::expect_at_least;
using workbook::testing::expect_close;
using workbook::testing::rounding_tolerance;

namespace {

constexpr double degrees = std::numbers::pi / 180.0;

/// The tolerance of a rod's numbers: the rod is thin (its moment about its own axis is 1e-4 of
/// the others), so an inverse inertia computed another correct way, inverse(R I R^T), differs
/// from R I^-1 R^T in the 12th digit; a mistake changes the first.
double relative(double magnitude) { return 1e-9 * std::abs(magnitude); }

/// Checks every element of `actual` against `expected`, to `tolerance`, column by column.
void expect_matrix(const testing::Law& law, const Matrix3& expected, const Matrix3& actual, double tolerance,
                   const std::string& situation) {
    for (int c = 0; c < 3; ++c)
        expect_close(law, expected.column(c), actual.column(c), tolerance, "1/(kg m^2)",
                     situation + " (column " + std::to_string(c) + ")");
}

/// The worked example of the page: a 2 kg rod 1 m long, tilted 30 degrees, falling at 3 m/s, e = 0.5.
struct WorkedRod {
    double mass = 2.0, length = 1.0, theta = 30.0 * degrees, speed = 3.0, e = 0.5;
    RigidBody rod = thin_rod(mass, length, theta, {0, 0, 0.25}, {0, 0, -speed});
    RigidBody floor = ground();
    Vector3 end = rod_lower_end(rod, length);
    WorkedRod() { rod.restitution = e; }
    [[nodiscard]] double closed_form_impulse() const {
        const double c = std::cos(theta);
        return (1.0 + e) * mass * speed / (1.0 + 3.0 * c * c);
    }
};

}  // namespace

TEST_CASE("a 12 kg, 1 x 2 x 3 m box turned 90 degrees about z swaps its x and y moments",
          "[angular-impulse][step:1:world-inverse-inertia][points:2]") {
    const RigidBody box = make_box(12.0, {0.5, 1.0, 1.5}, {1, 2, 3}, from_axis_angle({0, 0, 1}, 90.0 * degrees));
    // Body moments m/12 (b^2 + c^2): 13, 10, 5 kg m^2; turned, the world x axis is the body's y.
    const Matrix3 expected = Matrix3::diagonal({1.0 / 10.0, 1.0 / 13.0, 1.0 / 5.0});
    expect_matrix(laws::world_inertia, expected, angular_impulse::world_inverse_inertia(box), rounding_tolerance(0.2, 64),
                  describe_body(box));
    const RigidBody wall = make_immovable_sphere(1.0, {0, 0, 0});
    expect_matrix(laws::immovable, Matrix3::zero(), angular_impulse::world_inverse_inertia(wall), 0.0,
                  "an immovable ball");
}

TEST_CASE("a box turned about an oblique axis: I_world^-1 undoes R I R^T", "[angular-impulse][step:1:world-inverse-inertia][points:2]") {
    const RigidBody box = make_box(2.5, {0.2, 0.7, 1.1}, {0, 0, 0}, from_axis_angle(normalized(Vector3{1, 2, 3}), 50.0 * degrees));
    const Vector3 spin{0.3, -2.0, 1.5};
    const Vector3 angular_momentum = box.inertia_world() * spin;
    expect_close(laws::world_inertia, spin, angular_impulse::world_inverse_inertia(box) * angular_momentum,
                 rounding_tolerance(2.0, 256), "rad/s", describe_body(box) + "; w = I_world^-1 (I_world w) for w = " +
                                                            testing::format(spin) + " rad/s");
}

TEST_CASE("a box 3 m from the origin spinning at 2 rad/s about z: its corner's velocity",
          "[angular-impulse][step:2:point-velocity][points:2]") {
    RigidBody box = make_box(1.0, {1.0, 0.5, 0.5}, {3, 0, 0}, {}, {0, 0.5, 0});
    box.angular_velocity = {0, 0, 2};
    const Vector3 corner{4, 0.5, 0.5};  // r = (1, 0.5, 0.5): w x r = (-1, 2, 0)
    expect_close(laws::point_velocity, Vector3{-1, 2.5, 0}, angular_impulse::point_velocity(box, corner), rounding_tolerance(3.0),
                 "m/s", describe_body(box) + "; point " + testing::format(corner) + " m");
}

TEST_CASE("two points of a spinning body keep their distance, and a turning platform carries its edge",
          "[angular-impulse][step:2:point-velocity][points:2]") {
    testing::SeededRandom random(testing::run_seed());
    for (int i = 0; i < 20; ++i) {
        const Vector3 body_centre = random.vector(5.0);
        const RigidBody body = random_box(random, body_centre);
        const Vector3 p = body.position + random.vector(1.0);
        const Vector3 q = body.position + random.vector(1.0);
        const double along = dot(angular_impulse::point_velocity(body, p) - angular_impulse::point_velocity(body, q), p - q);
        expect_close(laws::rigid, 0.0, along, rounding_tolerance(100.0, 64), "m^2/s",
                     describe_body(body) + "; p = " + testing::format(p) + ", q = " + testing::format(q));
    }
    RigidBody platform = make_immovable_sphere(2.0, {0, 0, -1});
    platform.angular_velocity = {0, 0, 0.5};
    expect_close(laws::point_velocity, Vector3{0, 1, 0}, angular_impulse::point_velocity(platform, {2, 0, -1}), 1e-15, "m/s",
                 "a kinematic platform turning at 0.5 rad/s about z, its edge 2 m from the axis");
}

TEST_CASE("the worked example: a rod tilted 30 degrees falls at 3 m/s onto one end, e = 0.5",
          "[angular-impulse][step:3:impulse-size][points:2]") {
    const WorkedRod w;
    const double j = angular_impulse::impulse_magnitude(w.rod, w.floor, w.end, {0, 0, 1}, w.e);
    expect_close(laws::rod, w.closed_form_impulse(), j, relative(w.closed_form_impulse()), "N s",
                 "rod m = 2 kg, L = 1 m, theta = 30 deg, u = 3 m/s, e = 0.5, hitting the ground at its lower end " +
                     testing::format(w.end) + " m");
}

TEST_CASE("through the centres (r x n = 0) the impulse is chapter 3's", "[angular-impulse][step:3:impulse-size][points:2]") {
    RigidBody ball1 = make_sphere(2.0, 0.5, {0, 0, 0}, {3, 0, 0});
    ball1.angular_velocity = {0, 4, 0};  // a spin moves the point across n, not along it
    RigidBody box = make_box(1.0, {0.5, 0.3, 0.2}, {1.0, 0, 0}, {}, {-1, 0, 0});
    const Vector3 point{0.5, 0, 0};
    const Vector3 n{-1, 0, 0};  // from body 2 (the box) to body 1 (the ball)
    const double e = 0.75;
    const double u = dot(velocity_at(ball1, point) - velocity_at(box, point), n);
    const double expected = -(1.0 + e) * u / (ball1.inverse_mass + box.inverse_mass);
    expect_close(laws::central, expected, angular_impulse::impulse_magnitude(ball1, box, point, n, e),
                 rounding_tolerance(expected), "N s", pair_text(ball1, box) + "\npoint (0.5, 0, 0) m, n = (-1, 0, 0), e = 0.75");
}

TEST_CASE("random off-centre hits: J makes the point leave at -e u", "[angular-impulse][step:3:impulse-size][points:2]") {
    testing::SeededRandom random(testing::run_seed());
    for (int i = 0; i < 20; ++i) {
        RigidBody a = random_box(random, {0, 0, 0});
        const Vector3 b_centre = random.vector(2.0);
        RigidBody b = random_box(random, b_centre);
        const Vector3 n = random.direction();
        const Vector3 p = (a.position + b.position) / 2.0 + random.vector(0.3);
        const double u = normal_velocity_at(a, b, p, n);
        if (u >= 0.0) continue;
        const double e = random.uniform(0.0, 1.0);
        const std::string situation = pair_text(a, b) + "\npoint " + testing::format(p) + " m, n = " + testing::format(n) +
                                      ", e = " + testing::format(e);
        const double j = angular_impulse::impulse_magnitude(a, b, p, n, e);
        expect_at_least(laws::push, 0.0, j, 0.0, "N s", situation);
        // Apply J n by the laws of an impulse (dv = J n / m, dw = I^-1 (r x J n)) and measure u'.
        a.velocity += a.inverse_mass * j * n;
        a.angular_velocity += inverse(a.inertia_world()) * cross(p - a.position, j * n);
        b.velocity -= b.inverse_mass * j * n;
        b.angular_velocity -= inverse(b.inertia_world()) * cross(p - b.position, j * n);
        const double scale = length(a.velocity) + length(b.velocity) + 10.0 * (length(a.angular_velocity) + length(b.angular_velocity));
        expect_close(laws::restitution, -e * u, normal_velocity_at(a, b, p, n), rounding_tolerance(scale, 4096), "m/s",
                     situation + " (u' after applying J n)");
    }
}

TEST_CASE("the rod's impulse applied: v and w of the worked example", "[angular-impulse][step:4:apply-impulse][points:2]") {
    WorkedRod w;
    const double j = w.closed_form_impulse();
    const std::string situation = "rod m = 2 kg, L = 1 m, theta = 30 deg, u = 3 m/s, impulse " + testing::format(j) +
                                  " N s up at its lower end";
    angular_impulse::apply_impulse(w.rod, w.floor, w.end, Vector3{0, 0, j});
    expect_close(laws::impulse_response, Vector3{0, 0, -w.speed + j / w.mass}, w.rod.velocity, relative(3.0), "m/s",
                 situation + " (rod velocity after)");
    const double spin = 6.0 * j * std::cos(w.theta) / (w.mass * w.length);
    // The end lies at -x: pushing it up turns the rod about +y (r x F = (0, (L/2) cos theta J, 0)).
    expect_close(laws::impulse_response, Vector3{0, spin, 0}, w.rod.angular_velocity, relative(spin), "rad/s",
                 situation + " (rod angular velocity after)");
    expect_close(laws::immovable, Vector3{}, w.floor.velocity, 0.0, "m/s", situation + " (the ground after)");
    expect_close(laws::immovable, Vector3{}, w.floor.angular_velocity, 0.0, "rad/s", situation + " (the ground after)");
}

TEST_CASE("random impulses between two free boxes keep linear and angular momentum", "[angular-impulse][step:4:apply-impulse][points:2]") {
    testing::SeededRandom random(testing::run_seed());
    for (int i = 0; i < 20; ++i) {
        const Vector3 a_centre = random.vector(3.0);
        RigidBody a = random_box(random, a_centre);
        const Vector3 b_centre = random.vector(3.0);
        RigidBody b = random_box(random, b_centre);
        const Vector3 p = random.vector(3.0);
        const Vector3 impulse = random.vector(5.0);
        const std::string situation = pair_text(a, b) + "\nimpulse " + testing::format(impulse) + " N s at " + testing::format(p) + " m";
        const Vector3 p_before = momentum(a, b);
        const Vector3 l_before = angular_momentum(a, b);
        const double p_scale = a.mass() * length(a.velocity) + b.mass() * length(b.velocity) + length(impulse);
        const double l_scale = length(l_before) + 10.0 * p_scale;
        const Vector3 v1_before = a.velocity;
        const RigidBody a_sent = a;
        const RigidBody b_sent = b;
        angular_impulse::apply_impulse(a, b, p, impulse);
        expect_close(laws::impulse_response, v1_before + a_sent.inverse_mass * impulse, a.velocity, rounding_tolerance(p_scale * a_sent.inverse_mass, 64),
                     "m/s", situation + " (body 1 velocity after)");
        expect_close(laws::momentum, p_before, momentum(testing::judged(a_sent, a), testing::judged(b_sent, b)), rounding_tolerance(p_scale, 64), "kg m/s",
                     situation);
        expect_close(laws::angular_momentum, l_before, angular_momentum(testing::judged(a_sent, a), testing::judged(b_sent, b)), rounding_tolerance(l_scale, 1024), "kg m^2/s",
                     situation + " (about the origin)");
    }
}

TEST_CASE("resolve: the worked rod's end leaves the ground at -e u", "[angular-impulse][step:5:one-point][points:2]") {
    WorkedRod w;
    const std::string situation = "rod m = 2 kg, L = 1 m, theta = 30 deg, u = 3 m/s, e = 0.5, one contact point at its lower end";
    const Contact contact = contact_at({0, 0, 1}, w.end);
    angular_impulse::resolve(w.rod, w.floor, contact);
    expect_close(laws::restitution, w.e * w.speed, normal_velocity_at(w.rod, w.floor, w.end, {0, 0, 1}), relative(3.0),
                 "m/s", situation + " (the end's upward velocity after)");
    const double spin = 6.0 * w.closed_form_impulse() * std::cos(w.theta) / (w.mass * w.length);
    expect_close(laws::rod, spin, w.rod.angular_velocity.y, relative(spin), "rad/s", situation + " (spin about +y)");
}

TEST_CASE("resolve at e = 1 keeps the kinetic energy; a receding point is left alone", "[angular-impulse][step:5:one-point][points:2]") {
    RigidBody box = make_box(3.0, {0.4, 0.2, 0.3}, {0, 0, 0}, from_axis_angle(normalized(Vector3{1, -1, 2}), 0.7), {0.5, -2, 0.2});
    box.angular_velocity = {1, 0.5, -2};
    box.restitution = 1.0;
    RigidBody ball = make_sphere(0.8, 0.2, {0.2, -0.55, 0.1}, {0, 1.5, 0});
    ball.restitution = 1.0;
    const Vector3 point{0.15, -0.36, 0.05};
    const Contact contact = contact_at({0, 1, 0}, point);  // from the ball (body 2) up to the box (body 1)
    const std::string situation = pair_text(box, ball) + "\npoint " + testing::format(point) + " m, n = (0, 1, 0), e = 1";
    const double before = kinetic(box) + kinetic(ball);
    const double u = normal_velocity_at(box, ball, point, {0, 1, 0});
    const RigidBody box_sent = box;
    const RigidBody ball_sent = ball;
    angular_impulse::resolve(box, ball, contact);
    expect_close(laws::restitution, -u, normal_velocity_at(testing::judged(box_sent, box), testing::judged(ball_sent, ball), point, {0, 1, 0}),
                 rounding_tolerance(10.0, 64), "m/s", situation + " (u' at the point after; u = " + testing::format(u) + " m/s before)");
    expect_close(laws::energy, before, kinetic(testing::judged(box_sent, box)) + kinetic(testing::judged(ball_sent, ball)),
                 rounding_tolerance(before, 256), "J", situation);

    RigidBody away1 = box;
    RigidBody away2 = ball;
    away1.velocity = {0, 3, 0};
    away1.angular_velocity = {};
    const RigidBody copy1 = away1;
    const RigidBody copy2 = away2;
    angular_impulse::resolve(away1, away2, contact);
    const std::string receding = pair_text(copy1, copy2) + "\nthe point recedes";
    expect_close(laws::separating, copy1.velocity, away1.velocity, 0.0, "m/s", receding + " (body 1 velocity)");
    expect_close(laws::separating, copy1.angular_velocity, away1.angular_velocity, 0.0, "rad/s", receding + " (body 1 spin)");
    expect_close(laws::separating, copy2.velocity, away2.velocity, 0.0, "m/s", receding + " (body 2 velocity)");
}

TEST_CASE("a spinning box: its corner, not its centre, says whether the contact approaches", "[angular-impulse][step:5:one-point][points:2]") {
    // A 1 m cube resting on the ground touches it along its lower right edge, r = (0.5, 0, -0.5)
    // from its centre. Spinning at w about y moves that point's height at vz - 0.5 wy.
    const Vector3 point{0.5, 0, 0};
    const Contact contact = contact_at({0, 0, 1}, point);
    RigidBody floor = ground();
    const auto cube = [](double vz, double wy) {
        RigidBody box = make_box(2.0, {0.5, 0.5, 0.5}, {0, 0, 0.5}, {}, {0, 0, vz});
        box.angular_velocity = {0, wy, 0};
        box.restitution = 0.5;
        return box;
    };

    // Centre sinking at 1 m/s, spin lifting the edge at 2 m/s: the point recedes at 1 m/s.
    RigidBody sinking = cube(-1.0, -4.0);
    const RigidBody sinking_before = sinking;
    const std::string receding = "box m = 2 kg, 1 m cube on the ground, centre v = (0, 0, -1) m/s, w = (0, -4, 0) rad/s, "
                                 "e = 0.5\ncontact point " + testing::format(point) + " m (its edge), moving up at 1 m/s";
    angular_impulse::resolve(sinking, floor, contact);
    expect_close(laws::contact_point, sinking_before.velocity, sinking.velocity, 0.0, "m/s", receding + " (velocity after)");
    expect_close(laws::contact_point, sinking_before.angular_velocity, sinking.angular_velocity, 0.0, "rad/s",
                 receding + " (angular velocity after)");

    // Centre rising at 1 m/s, spin driving the edge down at 2 m/s: the point approaches at 1 m/s.
    RigidBody rising = cube(1.0, 4.0);
    const std::string approaching = "box m = 2 kg, 1 m cube on the ground, centre v = (0, 0, 1) m/s, w = (0, 4, 0) rad/s, "
                                    "e = 0.5\ncontact point " + testing::format(point) + " m (its edge), moving down at 1 m/s";
    angular_impulse::resolve(rising, floor, contact);
    expect_close(laws::contact_point, 0.5, normal_velocity_at(rising, floor, point, {0, 0, 1}), rounding_tolerance(4.0, 64), "m/s",
                 approaching + " (the point's upward velocity after: -e u = 0.5 m/s)");
}

TEST_CASE("a 2 x 1 x 1 box falling flat at 4 m/s onto four corners bounces straight, e = 0.5",
          "[angular-impulse][step:6:several-points][points:2]") {
    const Vector3 half{1.0, 0.5, 0.5};
    RigidBody box = make_box(3.0, half, {0, 0, 0.5}, {}, {0, 0, -4});
    box.restitution = 0.5;
    RigidBody floor = ground();
    const Contact contact = contact_at({0, 0, 1}, Vector3{-1, -0.5, 0}, Vector3{1, -0.5, 0}, Vector3{1, 0.5, 0}, Vector3{-1, 0.5, 0});
    const std::string situation = "box m = 3 kg, half extents (1, 0.5, 0.5) m, falling flat at 4 m/s, e = 0.5, four corner points";
    angular_impulse::resolve(box, floor, contact);
    expect_close(laws::flat, Vector3{0, 0, 2}, box.velocity, 1e-9, "m/s", situation + " (velocity after)");
    expect_close(laws::flat, Vector3{}, box.angular_velocity, 1e-9, "rad/s", situation + " (angular velocity after)");
}

TEST_CASE("a box landing on an edge turns as the closed form says, e = 0.8", "[angular-impulse][step:6:several-points][points:2]") {
    // A 1 x 1 x 2 box (half extents 0.5, 0.5, 1) tilted 20 degrees about x lands on its lower edge.
    const double mass = 2.0, e = 0.8, speed = 2.0, tilt = 20.0 * degrees;
    const Vector3 half{0.5, 0.5, 1.0};
    const Quaternion turn = from_axis_angle({1, 0, 0}, tilt);
    const Vector3 corner_body{0, -0.5, -1.0};
    const Vector3 r = rotate(turn, corner_body);  // lever arm of the edge's midpoint
    RigidBody box = make_box(mass, half, Vector3{0, 0, -r.z}, turn, {0, 0, -speed});
    box.restitution = e;
    RigidBody floor = ground();
    const Vector3 middle = box.position + r;
    const Contact contact = contact_at({0, 0, 1}, middle + Vector3{-0.5, 0, 0}, middle + Vector3{0.5, 0, 0});
    const double moment = mass / 3.0 * (half.y * half.y + half.z * half.z);  // about x
    const double d = r.y;
    const double total = (1.0 + e) * speed / (1.0 / mass + d * d / moment);
    const std::string situation = "box m = 2 kg, half extents (0.5, 0.5, 1) m, tilted 20 deg about x, falling at 2 m/s onto "
                                  "its edge (two points), e = 0.8";
    angular_impulse::resolve(box, floor, contact);
    expect_close(laws::edge, Vector3{0, 0, -speed + total / mass}, box.velocity, rounding_tolerance(speed, 1e6), "m/s",
                 situation + " (velocity after)");
    expect_close(laws::edge, Vector3{d * total / moment, 0, 0}, box.angular_velocity, 1e-9, "rad/s", situation + " (angular velocity after)");
    for (std::uint8_t i = 0; i < contact.point_count; ++i)
        expect_close(laws::every_point, e * speed, normal_velocity_at(box, floor, contact.points[i].position, {0, 0, 1}), 1e-9, "m/s",
                     situation + " (point " + std::to_string(i + 1) + " after)");
}
