#pragma once
/// \file
/// 3x3 matrices for inertia tensors and rotations.

#include <array>

#include "workbook/vector3.hpp"

namespace workbook {

/// A row-major 3x3 matrix in double precision.
struct Matrix3 {
    std::array<double, 9> m{};  ///< m[3 * row + column]

    /// The zero matrix.
    static constexpr Matrix3 zero() { return {}; }
    /// The identity matrix.
    static constexpr Matrix3 identity() { return diagonal({1.0, 1.0, 1.0}); }
    /// The diagonal matrix with `d` on its diagonal.
    static constexpr Matrix3 diagonal(const Vector3& d) { return {{d.x, 0, 0, 0, d.y, 0, 0, 0, d.z}}; }

    /// The element at (row, column), both counted from 0.
    constexpr double operator()(int row, int column) const { return m[static_cast<std::size_t>(3 * row + column)]; }
    /// The element at (row, column), writable.
    constexpr double& operator()(int row, int column) { return m[static_cast<std::size_t>(3 * row + column)]; }

    /// Row `r` as a vector.
    constexpr Vector3 row(int r) const { return {(*this)(r, 0), (*this)(r, 1), (*this)(r, 2)}; }
    /// Column `c` as a vector.
    constexpr Vector3 column(int c) const { return {(*this)(0, c), (*this)(1, c), (*this)(2, c)}; }

    /// Exact, element-wise equality.
    friend constexpr bool operator==(const Matrix3&, const Matrix3&) = default;
};

/// Matrix times column vector.
constexpr Vector3 operator*(const Matrix3& a, const Vector3& v) { return {dot(a.row(0), v), dot(a.row(1), v), dot(a.row(2), v)}; }

/// Matrix product a b.
constexpr Matrix3 operator*(const Matrix3& a, const Matrix3& b) {
    Matrix3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = dot(a.row(i), b.column(j));
    return r;
}

/// Every element scaled by `s`.
constexpr Matrix3 operator*(Matrix3 a, double s) {
    for (double& e : a.m) e *= s;
    return a;
}

/// Element-wise sum.
constexpr Matrix3 operator+(Matrix3 a, const Matrix3& b) {
    for (std::size_t i = 0; i < 9; ++i) a.m[i] += b.m[i];
    return a;
}

/// The transpose.
constexpr Matrix3 transpose(const Matrix3& a) {
    Matrix3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = a(j, i);
    return r;
}

/// The determinant.
constexpr double determinant(const Matrix3& a) { return dot(a.row(0), cross(a.row(1), a.row(2))); }

/// Inverse by the adjugate. A singular matrix yields the zero matrix, which is exactly the
/// inverse inertia an immovable body needs, so callers never see NaN from here.
constexpr Matrix3 inverse(const Matrix3& a) {
    const double det = determinant(a);
    if (det == 0.0) return Matrix3::zero();
    const Vector3 c0 = cross(a.row(1), a.row(2));
    const Vector3 c1 = cross(a.row(2), a.row(0));
    const Vector3 c2 = cross(a.row(0), a.row(1));
    const double s = 1.0 / det;
    return {{c0.x * s, c1.x * s, c2.x * s, c0.y * s, c1.y * s, c2.y * s, c0.z * s, c1.z * s, c2.z * s}};
}

}  // namespace workbook
