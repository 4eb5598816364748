// Mutant of chapter 6 for the grader's tests: t2 = t1 x n instead of n x t1: the frame is left-handed
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

std::array<Vector3, 2> tangent_basis(const Vector3& normal) {
    const double ax = std::abs(normal.x), ay = std::abs(normal.y), az = std::abs(normal.z);
    const Vector3 axis = ax <= ay && ax <= az ? Vector3{1, 0, 0} : ay <= az ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
    const Vector3 t1 = normalized(cross(normal, axis));
    return {t1, cross(t1, normal)};
}

}  // namespace workbook::friction
