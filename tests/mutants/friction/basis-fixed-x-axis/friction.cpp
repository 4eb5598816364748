// Mutant of chapter 6 for the grader's tests: t1 is the normalised cross product of the normal with the x axis, whatever the normal: a zero vector normalised (NaN) for a normal along x
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

std::array<Vector3, 2> tangent_basis(const Vector3& normal) {
    const Vector3 t1 = normalized(cross(normal, Vector3{1, 0, 0}));
    return {t1, cross(normal, t1)};
}

}  // namespace workbook::friction
