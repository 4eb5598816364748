#pragma once
/// \file
/// Double-precision 3D vector: the one value type every stage of the engine shares.

#include <cmath>

/// The workbook's engine: vectors and matrices, rigid bodies, contacts and their detection,
/// the world that steps them, and the probes that measure energy and momentum. Each
/// chapter's exercise lives in a nested namespace, such as workbook::inelastic.
namespace workbook {

/// A 3D vector in double precision. Planar scenes simply keep z = 0.
struct Vector3 {
    double x = 0.0;  ///< x component
    double y = 0.0;  ///< y component
    double z = 0.0;  ///< z component

    /// Adds `o` component-wise.
    constexpr Vector3& operator+=(const Vector3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    /// Subtracts `o` component-wise.
    constexpr Vector3& operator-=(const Vector3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    /// Scales every component by `s`.
    constexpr Vector3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
    /// Divides every component by `s`.
    constexpr Vector3& operator/=(double s) { x /= s; y /= s; z /= s; return *this; }

    /// Component-wise sum.
    friend constexpr Vector3 operator+(Vector3 a, const Vector3& b) { return a += b; }
    /// Component-wise difference.
    friend constexpr Vector3 operator-(Vector3 a, const Vector3& b) { return a -= b; }
    /// The opposite vector.
    friend constexpr Vector3 operator-(const Vector3& a) { return {-a.x, -a.y, -a.z}; }
    /// The vector scaled by `s`.
    friend constexpr Vector3 operator*(Vector3 a, double s) { return a *= s; }
    /// The vector scaled by `s`.
    friend constexpr Vector3 operator*(double s, Vector3 a) { return a *= s; }
    /// The vector divided by `s`.
    friend constexpr Vector3 operator/(Vector3 a, double s) { return a /= s; }
    /// Exact, component-wise equality.
    friend constexpr bool operator==(const Vector3&, const Vector3&) = default;
};

/// Dot product a . b.
constexpr double dot(const Vector3& a, const Vector3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// Cross product a x b (right-handed).
constexpr Vector3 cross(const Vector3& a, const Vector3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// |v|^2, without a square root.
constexpr double length_squared(const Vector3& v) { return dot(v, v); }
/// Euclidean length |v|.
inline double length(const Vector3& v) { return std::sqrt(length_squared(v)); }

/// True when every component is a finite number (no NaN, no infinity).
inline bool is_finite(const Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// The unit vector along v. The caller guarantees v is not the zero vector;
/// detection handles the degenerate cases itself so that no NaN is ever produced here.
inline Vector3 normalized(const Vector3& v) { return v / length(v); }

}  // namespace workbook
