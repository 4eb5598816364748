// Correct variant of chapter 6 for the grader's tests: the branchless orthonormal basis of Duff et al. (2017), another right-handed frame
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

std::array<Vector3, 2> tangent_basis(const Vector3& normal) {
    const double s = std::copysign(1.0, normal.z);
    const double a = -1.0 / (s + normal.z);
    const double b = normal.x * normal.y * a;
    const Vector3 t1{1.0 + s * normal.x * normal.x * a, s * b, -s * normal.x};
    const Vector3 t2{b, s + normal.y * normal.y * a, -normal.y};
    return {t1, t2};
}

}  // namespace workbook::friction
