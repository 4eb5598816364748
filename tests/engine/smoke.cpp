#include <catch2/catch_test_macros.hpp>

#include "workbook/vector3.hpp"

TEST_CASE("cross product of x and y is z", "[math]") {
    using workbook::Vector3;
    CHECK(workbook::cross(Vector3{1, 0, 0}, Vector3{0, 1, 0}) == Vector3{0, 0, 1});
}
