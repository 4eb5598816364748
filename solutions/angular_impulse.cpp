// Reference solution for chapter 4, angular impulses.
#include "angular-impulse.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "workbook/restitution.hpp"

namespace workbook::angular_impulse {

Matrix3 world_inverse_inertia(const RigidBody& body) {
    if (body.is_immovable()) return Matrix3::zero();
    // Rotate into the body frame (R^T), scale by the body-frame inverse, rotate back (R).
    const Matrix3 r = to_matrix(body.orientation);
    return r * inverse(body.inertia_body) * transpose(r);
}

Vector3 point_velocity(const RigidBody& body, const Vector3& point) {
    return body.velocity + cross(body.angular_velocity, point - body.position);
}

double impulse_denominator(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    const Vector3 r1 = point - body1.position;
    const Vector3 r2 = point - body2.position;
    const Vector3 turn1 = cross(world_inverse_inertia(body1) * cross(r1, normal), r1);
    const Vector3 turn2 = cross(world_inverse_inertia(body2) * cross(r2, normal), r2);
    return (body1.inverse_mass + body2.inverse_mass) * dot(normal, normal) + dot(normal, turn1 + turn2);
}

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal,
                         double restitution) {
    const double k = impulse_denominator(body1, body2, point, normal);
    if (k == 0.0) return 0.0;  // two immovable bodies: nothing can be pushed
    const double u = dot(point_velocity(body1, point) - point_velocity(body2, point), normal);
    return -(1.0 + restitution) * u / k;
}

void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    // An immovable body has inverse mass 0 and a zero inverse inertia, so it is left as it is.
    body1.velocity += body1.inverse_mass * impulse;
    body1.angular_velocity += world_inverse_inertia(body1) * cross(point - body1.position, impulse);
    body2.velocity -= body2.inverse_mass * impulse;
    body2.angular_velocity -= world_inverse_inertia(body2) * cross(point - body2.position, impulse);
}

namespace {

constexpr std::size_t max_points = max_contact_points;
using Column = std::array<double, max_points>;
using Square = std::array<Column, max_points>;

/// The relative velocity at `point` along `normal`: negative while the point approaches.
double normal_velocity(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    return dot(point_velocity(body1, point) - point_velocity(body2, point), normal);
}

/// A[i][j]: how much u_i changes per unit impulse +n on body 1 (and -n on body 2) at point j.
/// Measured with steps 2 and 4 on copies of the bodies at rest, so it is the same algebra as
/// step 3's denominator (A[i][i] = k_i) and no velocity cancels against another.
Square response_matrix(const RigidBody& body1, const RigidBody& body2, const Contact& contact) {
    Square a{};
    for (std::size_t j = 0; j < contact.point_count; ++j) {
        RigidBody probe1 = body1;
        RigidBody probe2 = body2;
        probe1.velocity = probe2.velocity = probe1.angular_velocity = probe2.angular_velocity = Vector3{};
        apply_impulse(probe1, probe2, contact.points[j].position, contact.normal);
        for (std::size_t i = 0; i < contact.point_count; ++i)
            a[i][j] = normal_velocity(probe1, probe2, contact.points[i].position, contact.normal);
    }
    return a;
}

/// Solves A_SS x = b_S for the points in `subset` by Gaussian elimination with partial
/// pivoting; false when A_SS is singular (a flat box's four points: only three motions).
bool solve_subset(const Square& a, const Column& b, unsigned subset, std::size_t count, Column& x) {
    std::array<std::size_t, max_points> index{};
    std::size_t n = 0;
    double scale = 0.0;
    for (std::size_t i = 0; i < count; ++i)
        if (subset & (1u << i)) {
            index[n++] = i;
            scale = std::max(scale, std::abs(a[i][i]));
        }
    std::array<std::array<double, max_points + 1>, max_points> m{};
    for (std::size_t r = 0; r < n; ++r) {
        for (std::size_t c = 0; c < n; ++c) m[r][c] = a[index[r]][index[c]];
        m[r][n] = b[index[r]];
    }
    for (std::size_t c = 0; c < n; ++c) {
        std::size_t pivot = c;
        for (std::size_t r = c + 1; r < n; ++r)
            if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
        if (std::abs(m[pivot][c]) <= 1e-12 * scale) return false;
        std::swap(m[c], m[pivot]);
        for (std::size_t r = c + 1; r < n; ++r) {
            const double f = m[r][c] / m[c][c];
            for (std::size_t k = c; k <= n; ++k) m[r][k] -= f * m[c][k];
        }
    }
    x = Column{};
    for (std::size_t r = n; r-- > 0;) {
        double sum = m[r][n];
        for (std::size_t k = r + 1; k < n; ++k) sum -= m[r][k] * x[index[k]];
        x[index[r]] = sum / m[r][r];
    }
    return true;
}

std::size_t bits(unsigned v) {
    std::size_t n = 0;
    for (; v != 0; v &= v - 1) ++n;
    return n;
}

}  // namespace

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    const std::size_t count = contact.point_count;
    const double e = combined_restitution(body1, body2);
    Column u{};
    Column target{};
    bool approaching = false;
    for (std::size_t i = 0; i < count; ++i) {
        u[i] = normal_velocity(body1, body2, contact.points[i].position, n);
        approaching = approaching || u[i] < 0.0;
        target[i] = u[i] < 0.0 ? -e * u[i] : 0.0;  // a point that does not approach must not start to
    }
    if (!approaching) return;

    if (count == 1) {
        const Vector3& p = contact.points[0].position;
        apply_impulse(body1, body2, p, impulse_magnitude(body1, body2, p, n, e) * n);
        return;
    }

    // Several points, solved together: find impulses J_i >= 0 with u' = u + A J >= target and
    // u'_i = target_i wherever J_i > 0. Try the points that push, largest sets first: solve
    // A_SS J_S = (target - u)_S and keep the first answer whose impulses are >= 0 and whose other
    // points do not approach faster than their targets. At most 2^4 - 1 = 15 systems of at most
    // 4 x 4; a flat box is done by its first set of three.
    const Square a = response_matrix(body1, body2, contact);
    Column wanted{};
    double size = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        wanted[i] = target[i] - u[i];
        size = std::max(size, std::abs(u[i]) + std::abs(target[i]));
    }
    const unsigned all = (1u << count) - 1u;
    for (std::size_t pushing = count; pushing > 0; --pushing) {
        for (unsigned subset = all; subset > 0; --subset) {
            if (bits(subset) != pushing) continue;
            Column impulse{};
            if (!solve_subset(a, wanted, subset, count, impulse)) continue;
            double largest = 0.0;
            for (std::size_t i = 0; i < count; ++i) largest = std::max(largest, std::abs(impulse[i]));
            bool valid = true;
            for (std::size_t i = 0; i < count && valid; ++i) {
                if (impulse[i] < -1e-12 * largest) valid = false;
                double after = u[i];
                for (std::size_t j = 0; j < count; ++j) after += a[i][j] * impulse[j];
                if (after < target[i] - 1e-12 * size) valid = false;
            }
            if (!valid) continue;
            for (std::size_t i = 0; i < count; ++i)
                if (impulse[i] > 0.0) apply_impulse(body1, body2, contact.points[i].position, impulse[i] * n);
            return;
        }
    }
    // Unreachable for a physical contact (the problem always has a solution); kept finite.
}

}  // namespace workbook::angular_impulse
