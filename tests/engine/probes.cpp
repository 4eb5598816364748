// Energy and momentum probes on bodies whose quantities have closed forms.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <limits>
#include <numbers>
#include <vector>

#include "checks.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
using workbook::engine_tests::is_close_to;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
const Vector3 earth_gravity{0.0, -9.81, 0.0};

/// Immovable bodies given a velocity anyway: the probes must ignore them even then.
std::vector<RigidBody> moving_environment() {
    RigidBody ground = make_immovable_plane({0, 1, 0}, {0, -1, 0});
    ground.velocity = {1, 2, 3};
    RigidBody post = make_immovable_sphere(0.5, {3, 3, 3});
    post.velocity = {-4, 0, 0};
    post.angular_velocity = {0, 5, 0};
    return {ground, post};
}

}  // namespace

TEST_CASE("a spinning sphere has rotational energy 1/2 (2/5 m r^2) w^2 and spin I w", "[probes]") {
    RigidBody ball = make_sphere(2.0, 0.5, {0, 0, 0});
    ball.angular_velocity = {0, 0, 3};
    const std::vector<RigidBody> bodies{ball};

    const Probes p = measure(bodies, {});
    const double inertia = 0.4 * 2.0 * 0.5 * 0.5;  // 0.2 kg m^2
    CHECK_THAT(p.kinetic_rotational, WithinAbs(0.5 * inertia * 9.0, 4 * eps));
    CHECK_THAT(p.kinetic_rotational, WithinAbs(0.9, 4 * eps));
    CHECK(p.kinetic_linear == 0.0);
    CHECK(p.linear_momentum == Vector3{});
    CHECK_THAT(p.angular_momentum, is_close_to(Vector3{0, 0, 0.6}, 4 * eps));
    CHECK_THAT(kinetic_energy(ball), WithinAbs(0.9, 4 * eps));
}

TEST_CASE("linear energy 1/2 m |v|^2, momentum m v, potential -m g . x", "[probes]") {
    const RigidBody ball = make_sphere(2.0, 0.5, {4, 3, -1}, {1, 2, 2});
    const std::vector<RigidBody> bodies{ball};

    const Probes p = measure(bodies, earth_gravity);
    CHECK(p.kinetic_linear == 9.0);  // 1/2 * 2 * 9
    CHECK(p.kinetic_rotational == 0.0);
    CHECK(p.linear_momentum == Vector3{2, 4, 4});
    CHECK_THAT(p.potential, WithinAbs(2.0 * 9.81 * 3.0, 4 * eps * 58.86));
    CHECK(p.kinetic() == 9.0);
    CHECK(p.total_energy() == p.kinetic() + p.potential);
    CHECK(kinetic_energy(ball) == 9.0);
}

TEST_CASE("potential energy follows gravity in any direction, zero at the origin", "[probes]") {
    const std::vector<RigidBody> bodies{make_sphere(0.5, 0.1, {2, -6, 8})};
    CHECK(measure(bodies, {1, 2, 3}).potential == -0.5 * (2.0 - 12.0 + 24.0));
    CHECK(measure(bodies, {}).potential == 0.0);
    const std::vector<RigidBody> at_origin{make_sphere(0.5, 0.1, {0, 0, 0})};
    CHECK(measure(at_origin, earth_gravity).potential == 0.0);
}

TEST_CASE("angular momentum about the origin of a body passing it: x cross m v plus spin", "[probes]") {
    // Mass 3 moving at 2 m/s along x on the line y = 1: |L| = m v d = 6, pointing along -z,
    // wherever along the line the body is. Its spin about -z adds I w = 0.3 * 1.
    for (const double along : {-5.0, 0.0, 0.5, 5.0}) {
        CAPTURE(along);
        RigidBody ball = make_sphere(3.0, 0.5, {along, 1, 0}, {2, 0, 0});
        ball.angular_velocity = {0, 0, -1};
        const std::vector<RigidBody> bodies{ball};
        CHECK_THAT(measure(bodies, {}).angular_momentum, is_close_to(Vector3{0, 0, -6.3}, 8 * eps));
    }
}

TEST_CASE("probes sum over the movable bodies", "[probes]") {
    RigidBody first = make_sphere(3.0, 0.5, {5, 1, 0}, {2, 0, 0});
    first.angular_velocity = {0, 0, -1};
    const RigidBody second = make_sphere(1.0, 0.25, {0, 0, 2}, {0, -4, 0});
    const std::vector<RigidBody> bodies{first, second};

    const Probes p = measure(bodies, earth_gravity);
    CHECK(p.kinetic_linear == 0.5 * 3.0 * 4.0 + 0.5 * 1.0 * 16.0);
    CHECK_THAT(p.kinetic_rotational, WithinAbs(0.5 * 0.3 * 1.0, 4 * eps));
    CHECK(p.linear_momentum == Vector3{6, -4, 0});
    // x cross m v: (0, 0, -6) for the first body and (8, 0, 0) for the second.
    CHECK_THAT(p.angular_momentum, is_close_to(Vector3{8, 0, -6.3}, 8 * eps));
    CHECK_THAT(p.potential, WithinAbs(3.0 * 9.81 * 1.0, 4 * eps * 29.43));
}

TEST_CASE("immovable bodies are left out of every probe, even when given a velocity", "[probes][immovable]") {
    RigidBody ball = make_sphere(3.0, 0.5, {5, 1, 0}, {2, 0, 0});
    ball.angular_velocity = {0, 0, -1};
    std::vector<RigidBody> bodies{ball};
    const Probes alone = measure(bodies, earth_gravity);

    for (const RigidBody& body : moving_environment()) {
        CHECK(kinetic_energy(body) == 0.0);
        bodies.push_back(body);
    }
    const Probes with_environment = measure(bodies, earth_gravity);
    CHECK(with_environment.kinetic_linear == alone.kinetic_linear);
    CHECK(with_environment.kinetic_rotational == alone.kinetic_rotational);
    CHECK(with_environment.potential == alone.potential);
    CHECK(with_environment.linear_momentum == alone.linear_momentum);
    CHECK(with_environment.angular_momentum == alone.angular_momentum);

    const std::vector<RigidBody> only_environment = moving_environment();
    const Probes empty = measure(only_environment, earth_gravity);
    CHECK(empty.total_energy() == 0.0);
    CHECK(empty.linear_momentum == Vector3{});
    CHECK(empty.angular_momentum == Vector3{});
}

TEST_CASE("rotational energy uses the world-frame inertia of a turned body", "[probes]") {
    // A 12 kg box with half extents (1, 2, 3): body-frame inertia diag(52, 40, 20). Turned a
    // quarter about z, its body x axis lies along world y, so spinning about world y meets 52.
    RigidBody box;
    box.inverse_mass = 1.0 / 12.0;
    box.inertia_body = solid_box_inertia(12.0, {1, 2, 3});
    box.shape = Shape::box({1, 2, 3});
    box.orientation = from_axis_angle({0, 0, 1}, std::numbers::pi / 2);
    box.angular_velocity = {0, 2, 0};
    box.update_world_inertia();
    REQUIRE(box.inertia_body == Matrix3::diagonal({52, 40, 20}));

    const std::vector<RigidBody> bodies{box};
    const Probes p = measure(bodies, {});
    CHECK_THAT(p.kinetic_rotational, WithinAbs(0.5 * 52.0 * 4.0, 64 * eps));
    CHECK_THAT(p.angular_momentum, is_close_to(Vector3{0, 104, 0}, 64 * eps));
    CHECK_THAT(kinetic_energy(box), WithinAbs(104.0, 64 * eps));
    CHECK_THAT(box.inverse_inertia_world, is_close_to(Matrix3::diagonal({1.0 / 40, 1.0 / 52, 1.0 / 20}), 4 * eps));
}
