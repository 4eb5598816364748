#pragma once
/// \file
/// Catch2 support for the engine's value types, shared by the engine tests: printable
/// vectors and matrices, and matchers with an absolute per-component tolerance, so that a
/// failure shows both values in full rather than a bare "false".

#include <catch2/catch_tostring.hpp>
#include <catch2/matchers/catch_matchers.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "workbook/matrix3.hpp"
#include "workbook/quaternion.hpp"
#include "workbook/vector3.hpp"

template <>
struct Catch::StringMaker<workbook::Vector3> {
    static std::string convert(const workbook::Vector3& v) {
        std::ostringstream out;
        out.precision(17);
        out << '(' << v.x << ", " << v.y << ", " << v.z << ')';
        return out.str();
    }
};

template <>
struct Catch::StringMaker<workbook::Quaternion> {
    static std::string convert(const workbook::Quaternion& q) {
        std::ostringstream out;
        out.precision(17);
        out << '(' << q.w << "; " << q.x << ", " << q.y << ", " << q.z << ')';
        return out.str();
    }
};

template <>
struct Catch::StringMaker<workbook::Matrix3> {
    static std::string convert(const workbook::Matrix3& a) {
        std::ostringstream out;
        out.precision(17);
        for (int r = 0; r < 3; ++r) out << (r == 0 ? "[" : " ") << StringMaker<workbook::Vector3>::convert(a.row(r));
        out << ']';
        return out.str();
    }
};

namespace workbook::engine_tests {

inline double max_abs_difference(const Vector3& a, const Vector3& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

inline double max_abs_difference(const Quaternion& a, const Quaternion& b) {
    return std::max({std::abs(a.w - b.w), std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

inline double max_abs_difference(const Matrix3& a, const Matrix3& b) {
    double largest = 0.0;
    for (std::size_t i = 0; i < a.m.size(); ++i) largest = std::max(largest, std::abs(a.m[i] - b.m[i]));
    return largest;
}

/// Every component of the value lies within `tolerance` of the target's. A NaN anywhere fails.
template <typename T>
class WithinAbsEach final : public Catch::Matchers::MatcherBase<T> {
public:
    WithinAbsEach(const T& target, double tolerance) : target_(target), tolerance_(tolerance) {}

    bool match(const T& value) const override { return max_abs_difference(value, target_) <= tolerance_; }

    std::string describe() const override {
        std::ostringstream out;
        out << "is within " << tolerance_ << " of " << Catch::StringMaker<T>::convert(target_) << " in every component";
        return out.str();
    }

private:
    T target_;
    double tolerance_;
};

template <typename T>
WithinAbsEach<T> is_close_to(const T& target, double tolerance) {
    return {target, tolerance};
}

}  // namespace workbook::engine_tests
