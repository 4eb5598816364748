// Mutant of chapter 6 for the grader's tests: the z axis is special-cased only when the normal IS +z; -z still normalises a zero vector (NaN)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

std::array<Vector3, 2> tangent_basis(const Vector3& normal) {
    const Vector3 axis = normal == Vector3{0, 0, 1} ? Vector3{1, 0, 0} : Vector3{0, 0, 1};
    const Vector3 t1 = normalized(cross(normal, axis));
    return {t1, cross(normal, t1)};
}

}  // namespace workbook::friction
