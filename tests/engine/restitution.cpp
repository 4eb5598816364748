// The rule that combines two bodies' coefficients of restitution (workbook/restitution.hpp),
// which chapter 3's page explains and every chapter with restitution relies on.
#include <catch2/catch_test_macros.hpp>

#include "workbook/restitution.hpp"

using namespace workbook;

namespace {
RigidBody with_restitution(double e) {
    RigidBody body = make_sphere(1.0, 0.5, {});
    body.restitution = e;
    return body;
}
}  // namespace

TEST_CASE("combined restitution is the smaller of the two, symmetric, and e with itself", "[restitution]") {
    CHECK(combined_restitution(with_restitution(0.3), with_restitution(0.9)) == 0.3);
    CHECK(combined_restitution(with_restitution(0.9), with_restitution(0.3)) == 0.3);
    CHECK(combined_restitution(with_restitution(0.8), with_restitution(0.8)) == 0.8);
    // Clay sticks to anything; the ground's default e = 1 leaves the ball's value in charge.
    CHECK(combined_restitution(with_restitution(0.0), with_restitution(1.0)) == 0.0);
    const RigidBody ground = make_immovable_plane({0, 1, 0}, {});
    CHECK(ground.restitution == 1.0);
    CHECK(combined_restitution(with_restitution(0.8), ground) == 0.8);
}
