#include "workbook/box_detection.hpp"
#include "workbook/tolerances.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace workbook {

namespace {

/// A box in world space: centre, the three unit axes (columns of its rotation) and half extents.
struct OrientedBox {
    Vector3 centre;
    std::array<Vector3, 3> axis;
    std::array<double, 3> half;
};

OrientedBox oriented_box(const RigidBody& body) {
    const Matrix3 r = to_matrix(body.orientation);
    const Vector3& h = body.shape.half_extents;
    return {body.position, {r.column(0), r.column(1), r.column(2)}, {h.x, h.y, h.z}};
}

/// Half the length of the box's shadow on the unit direction n.
double shadow_radius(const OrientedBox& box, const Vector3& n) {
    return box.half[0] * std::abs(dot(box.axis[0], n)) + box.half[1] * std::abs(dot(box.axis[1], n)) +
           box.half[2] * std::abs(dot(box.axis[2], n));
}

double largest_half_extent(const OrientedBox& box) { return std::max({box.half[0], box.half[1], box.half[2]}); }

/// Where a relative tolerance needs a length: near-duplicate points, ties between faces.
constexpr double relative_tolerance = tolerances::geometric_tie;

/// A possible contact point before at most four are kept.
struct Candidate {
    Vector3 position;
    double depth = 0.0;
};

/// Up to 16 candidates: a box has 8 corners, and a quadrilateral clipped by four lines has 8.
class Candidates {
public:
    /// Adds a point, unless it coincides (within `merge_distance`) with one already there, in
    /// which case the deeper of the two is kept: a clipped polygon repeats a corner that lies
    /// exactly on a side plane, and two rows for one point would make a simultaneous solve singular.
    void add(const Vector3& position, double depth, double merge_distance) {
        for (std::size_t i = 0; i < count_; ++i) {
            if (length_squared(items_[i].position - position) <= merge_distance * merge_distance) {
                if (depth > items_[i].depth) items_[i] = {position, depth};
                return;
            }
        }
        if (count_ < items_.size()) items_[count_++] = {position, depth};
    }

    [[nodiscard]] std::size_t size() const { return count_; }
    [[nodiscard]] const Candidate& operator[](std::size_t i) const { return items_[i]; }

private:
    std::array<Candidate, 16> items_{};
    std::size_t count_ = 0;
};

/// Whether p comes before q in an order that does not depend on the order in which the
/// points were found: by x, then y, then z, each compared only beyond `tolerance`.
bool comes_first(const Vector3& p, const Vector3& q, double tolerance) {
    if (std::abs(p.x - q.x) > tolerance) return p.x < q.x;
    if (std::abs(p.y - q.y) > tolerance) return p.y < q.y;
    return p.z < q.z - tolerance;
}

/// Index of the candidate with the largest score(i), skipping the `taken_count` indices in
/// `taken`. Equal scores (within rounding) go to the point that comes first by position, so
/// that swapping the two bodies, which lists the same points in another order, keeps the same
/// ones: a regular octagon of equally deep points has many equally good choices of four.
template <typename Score>
std::size_t best_index(const Candidates& candidates, const std::array<std::size_t, 4>& taken, std::size_t taken_count,
                       double tolerance, Score score) {
    std::size_t best = candidates.size();
    double best_score = 0.0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (std::find(taken.begin(), taken.begin() + static_cast<std::ptrdiff_t>(taken_count), i) !=
            taken.begin() + static_cast<std::ptrdiff_t>(taken_count))
            continue;
        const double s = score(i);
        const bool tied = std::abs(s - best_score) <= relative_tolerance * std::max(std::abs(s), std::abs(best_score));
        if (best == candidates.size() || (!tied && s > best_score) ||
            (tied && comes_first(candidates[i].position, candidates[best].position, tolerance))) {
            best = i;
            best_score = s;
        }
    }
    return best;
}

/// Writes at most four of the candidates into `out`. With more than four, the manifold keeps
/// the deepest point (the one that matters most for separating the bodies), then the point
/// farthest from it, then the one making the largest triangle with those two, then the one
/// that adds the most area: the widest patch the four can span, so that a face resting on a
/// face is supported at its extremes and does not rock.
void keep_four(const Candidates& candidates, const Vector3& normal, double tolerance, Contact& out) {
    if (candidates.size() <= max_contact_points) {
        for (std::size_t i = 0; i < candidates.size(); ++i) out.add_point(candidates[i].position, candidates[i].depth);
        return;
    }
    std::array<std::size_t, 4> taken{};
    const auto at = [&](std::size_t i) { return candidates[i].position; };
    taken[0] = best_index(candidates, taken, 0, tolerance, [&](std::size_t i) { return candidates[i].depth; });
    const Vector3 a = at(taken[0]);
    taken[1] = best_index(candidates, taken, 1, tolerance, [&](std::size_t i) { return length_squared(at(i) - a); });
    const Vector3 b = at(taken[1]);
    // Twice the signed area of a triangle, as seen along the normal.
    const auto area = [&](const Vector3& p, const Vector3& q, const Vector3& r) { return dot(normal, cross(q - p, r - p)); };
    taken[2] = best_index(candidates, taken, 2, tolerance, [&](std::size_t i) { return std::abs(area(a, b, at(i))); });
    const Vector3 c = at(taken[2]);
    // The hull of four points is the largest of the three quadrilaterals through them (twice
    // a quadrilateral's area is the cross product of its diagonals).
    taken[3] = best_index(candidates, taken, 3, tolerance, [&](std::size_t i) {
        const Vector3 d = at(i);
        return std::max({std::abs(dot(normal, cross(c - a, d - b))), std::abs(dot(normal, cross(d - a, c - b))),
                         std::abs(dot(normal, cross(b - a, c - d)))});
    });
    for (std::size_t i : taken) out.add_point(candidates[i].position, candidates[i].depth);
}

/// A convex polygon of at most 8 vertices (a quadrilateral clipped by up to four planes).
struct Polygon {
    std::array<Vector3, 8> vertex{};
    std::size_t count = 0;
};

/// Sutherland-Hodgman: the part of `polygon` where dot(p, plane_normal) <= plane_offset.
Polygon clip(const Polygon& polygon, const Vector3& plane_normal, double plane_offset) {
    Polygon kept;
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const Vector3& p = polygon.vertex[i];
        const Vector3& q = polygon.vertex[(i + 1) % polygon.count];
        const double dp = dot(p, plane_normal) - plane_offset;
        const double dq = dot(q, plane_normal) - plane_offset;
        if (dp <= 0.0 && kept.count < kept.vertex.size()) kept.vertex[kept.count++] = p;
        if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
            if (kept.count < kept.vertex.size()) kept.vertex[kept.count++] = p + (q - p) * (dp / (dp - dq));
        }
    }
    return kept;
}

/// The result of the separating-axis test: the axis of least overlap, oriented from body 2
/// towards body 1, and which feature pair it came from.
struct Separation {
    enum class Kind { face_of_a, face_of_b, edges } kind = Kind::face_of_a;
    Vector3 normal{};
    double overlap = 0.0;
    int index_a = 0;  ///< face axis of a, or the edge direction of a
    int index_b = 0;  ///< face axis of b, or the edge direction of b
};

/// Face-face contact: `reference` owns the face whose outward normal is `outward` (unit, along
/// one of its axes, index `face_axis`); the face of `incident` turned most against it is
/// clipped to the reference face's sides, and the clipped corners behind the face, or on it to
/// within `touching`, are kept; so are those in front of it by less than `reach` (speculative
/// points, their depth the gap, negative).
void clip_incident_face(const OrientedBox& reference, int face_axis, const Vector3& outward,
                        const OrientedBox& incident, const Vector3& normal, double merge_distance, double touching,
                        double reach, Contact& out) {
    const auto f = static_cast<std::size_t>(face_axis);
    const Vector3 face_centre = reference.centre + outward * reference.half[f];
    const double face_offset = dot(face_centre, outward);

    std::size_t m = 0;
    for (std::size_t i = 1; i < 3; ++i)
        if (std::abs(dot(incident.axis[i], outward)) > std::abs(dot(incident.axis[m], outward))) m = i;
    const double facing = dot(incident.axis[m], outward) > 0.0 ? -1.0 : 1.0;
    const Vector3 incident_centre = incident.centre + incident.axis[m] * (facing * incident.half[m]);
    const Vector3 u = incident.axis[(m + 1) % 3] * incident.half[(m + 1) % 3];
    const Vector3 v = incident.axis[(m + 2) % 3] * incident.half[(m + 2) % 3];
    Polygon polygon{{incident_centre + u + v, incident_centre - u + v, incident_centre - u - v, incident_centre + u - v}, 4};

    for (std::size_t k = 1; k < 3; ++k) {
        const std::size_t side = (f + k) % 3;
        const Vector3& axis = reference.axis[side];
        const double centre = dot(reference.centre, axis);
        polygon = clip(polygon, axis, centre + reference.half[side]);
        polygon = clip(polygon, -axis, -(centre - reference.half[side]));
    }

    // A corner lying on the reference face is kept as a point of depth 0. A box resting on a
    // box keeps the depth it started with (both fall by the same g dt^2 a step), which for a
    // stack built touching is none: its corners sit on the face below to within rounding, and
    // a tilt of 1e-9 rad lifts one of them a hair in front. Dropping that corner would leave the
    // box on three points, free to turn about the diagonal through two of them, and the
    // impulses the four points carried last step, applied again at three, would turn it.
    Candidates candidates;
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const double depth = face_offset - dot(polygon.vertex[i], outward);
        if (depth > -touching)
            candidates.add(polygon.vertex[i] + outward * (depth / 2.0), std::max(depth, 0.0), merge_distance);
        else if (depth > -reach)
            candidates.add(polygon.vertex[i] + outward * (depth / 2.0), depth, merge_distance);
    }
    keep_four(candidates, normal, merge_distance, out);
}

/// Edge-edge contact: one point halfway between the closest points of the two supporting edges.
/// Edges apart by less than `touching` touch (depth 0); farther apart (a speculative point)
/// the depth is the gap along the normal, negative.
void edge_contact(const OrientedBox& a, const OrientedBox& b, const Separation& s, double touching, Contact& out) {
    const auto ia = static_cast<std::size_t>(s.index_a);
    const auto ib = static_cast<std::size_t>(s.index_b);
    // The edge of a parallel to its axis ia that reaches furthest towards b (along -normal),
    // and the edge of b parallel to ib that reaches furthest towards a (along +normal).
    Vector3 on_a = a.centre;
    Vector3 on_b = b.centre;
    for (std::size_t k = 0; k < 3; ++k) {
        if (k != ia) on_a += a.axis[k] * (dot(a.axis[k], s.normal) > 0.0 ? -a.half[k] : a.half[k]);
        if (k != ib) on_b += b.axis[k] * (dot(b.axis[k], s.normal) > 0.0 ? b.half[k] : -b.half[k]);
    }
    // Closest points of the lines on_a + p da and on_b + q db (unit directions).
    const Vector3& da = a.axis[ia];
    const Vector3& db = b.axis[ib];
    const Vector3 r = on_a - on_b;
    const double cosine = dot(da, db);
    const double denominator = 1.0 - cosine * cosine;  // > 0: parallel edges give no edge axis
    const double ra = dot(da, r);
    const double rb = dot(db, r);
    const double p = std::clamp((cosine * rb - ra) / denominator, -a.half[ia], a.half[ia]);
    const double q = std::clamp(rb + p * cosine, -b.half[ib], b.half[ib]);
    out.add_point((on_a + da * p + on_b + db * q) * 0.5, s.overlap > -touching ? std::max(s.overlap, 0.0) : s.overlap);
}

/// Below this length a cross product of two unit edge directions (the sine of their angle)
/// counts as parallel edges, whose separation the face axes already test. Normalising a
/// shorter one would turn rounding into a visibly wrong axis: its direction error is about
/// eps / length, so 1e-6 keeps a wrongly tilted axis below 1e-10 of the box size.
constexpr double parallel_edges = tolerances::parallel_edges;

/// The separating-axis test; false when some axis separates the boxes by more than `tie`
/// plus `reach` (0, or the reach of speculative contacts). Boxes that touch to within rounding
/// are in contact, with an overlap of (about) zero: a stack built of boxes exactly on each
/// other is held from its first step, instead of each box finding the one below only when
/// rounding happens to make them overlap. Boxes apart by less than the reach get the axis that
/// separates them most (the least overlap, negative), as overlapping boxes get the one that
/// separates them soonest.
bool least_overlap(const OrientedBox& a, const OrientedBox& b, double reach, Separation& result) {
    const Vector3 offset = a.centre - b.centre;
    const double tie = relative_tolerance * std::max(largest_half_extent(a), largest_half_extent(b));
    const double apart = -(tie + reach);

    // The overlap of the shadows on unit axis n, and n turned to point from b towards a.
    const auto overlap_on = [&](const Vector3& n, Vector3& towards_a) {
        const double distance = dot(offset, n);
        towards_a = distance >= 0.0 ? n : -n;
        return shadow_radius(a, n) + shadow_radius(b, n) - std::abs(distance);
    };

    Separation best_face_a{Separation::Kind::face_of_a, {}, 0.0, -1, 0};
    Separation best_face_b{Separation::Kind::face_of_b, {}, 0.0, 0, -1};
    for (int i = 0; i < 3; ++i) {
        Vector3 n;
        const double overlap = overlap_on(a.axis[static_cast<std::size_t>(i)], n);
        if (overlap <= apart) return false;
        if (best_face_a.index_a < 0 || overlap < best_face_a.overlap) best_face_a = {Separation::Kind::face_of_a, n, overlap, i, 0};
    }
    for (int j = 0; j < 3; ++j) {
        Vector3 n;
        const double overlap = overlap_on(b.axis[static_cast<std::size_t>(j)], n);
        if (overlap <= apart) return false;
        if (best_face_b.index_b < 0 || overlap < best_face_b.overlap) best_face_b = {Separation::Kind::face_of_b, n, overlap, 0, j};
    }
    Separation best_edges{Separation::Kind::edges, {}, 0.0, -1, -1};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Vector3 c = cross(a.axis[static_cast<std::size_t>(i)], b.axis[static_cast<std::size_t>(j)]);
            const double c_length = length(c);
            if (c_length < parallel_edges) continue;
            Vector3 n;
            const double overlap = overlap_on(c / c_length, n);
            if (overlap <= apart) return false;
            if (best_edges.index_a < 0 || overlap < best_edges.overlap) best_edges = {Separation::Kind::edges, n, overlap, i, j};
        }
    }

    // Between the two boxes' faces, the smaller overlap wins. A tie (parallel faces, as in a
    // stack) goes to the larger face, which then holds the clipped points; deciding by the
    // geometry and not by the order of a and b is what makes swapping them keep the points.
    const auto face_area = [](const OrientedBox& box, int axis) {
        const auto k = static_cast<std::size_t>(axis);
        return box.half[(k + 1) % 3] * box.half[(k + 2) % 3];
    };
    const Separation* face = &best_face_a;
    if (best_face_b.overlap < best_face_a.overlap - tie ||
        (std::abs(best_face_b.overlap - best_face_a.overlap) <= tie &&
         face_area(b, best_face_b.index_b) > face_area(a, best_face_a.index_a)))
        face = &best_face_b;
    // An edge axis must beat the faces clearly: when a face and an edge overlap about equally,
    // the face gives a stable patch of points where the edge gives one wandering point. Apart,
    // the edge must separate the boxes clearly more than the face does.
    constexpr double edge_must_beat_face = 0.95;
    const double edge_limit = face->overlap >= 0.0 ? edge_must_beat_face * face->overlap : face->overlap / edge_must_beat_face;
    result = (best_edges.index_a >= 0 && best_edges.overlap < edge_limit - tie) ? best_edges : *face;
    return true;
}

}  // namespace

bool collide_box_plane(const RigidBody& box, const RigidBody& plane, Contact& out, double reach) {
    out = Contact{};
    const OrientedBox b = oriented_box(box);
    const Vector3 normal = rotate(plane.orientation, plane.shape.normal);
    const double surface = dot(plane.position, normal);
    const double merge_distance = relative_tolerance * largest_half_extent(b);
    Candidates corners;
    for (int corner = 0; corner < 8; ++corner) {
        Vector3 p = b.centre;
        for (std::size_t k = 0; k < 3; ++k) p += b.axis[k] * (((corner >> k) & 1) != 0 ? b.half[k] : -b.half[k]);
        const double depth = surface - dot(p, normal);
        if (depth > -reach) corners.add(p + normal * (depth / 2.0), depth, merge_distance);  // reach 0: behind the plane
    }
    if (corners.size() == 0) return false;
    out.normal = normal;
    keep_four(corners, normal, merge_distance, out);
    return true;
}

bool collide_sphere_box(const RigidBody& sphere, const RigidBody& box, Contact& out, double reach) {
    out = Contact{};
    const OrientedBox b = oriented_box(box);
    const double radius = sphere.shape.radius;
    const Vector3 offset = sphere.position - b.centre;
    const std::array<double, 3> local{dot(offset, b.axis[0]), dot(offset, b.axis[1]), dot(offset, b.axis[2])};

    bool inside = true;
    Vector3 nearest = b.centre;  // the point of the box nearest to the sphere's centre
    for (std::size_t k = 0; k < 3; ++k) {
        const double clamped = std::clamp(local[k], -b.half[k], b.half[k]);
        inside = inside && clamped == local[k];
        nearest += b.axis[k] * clamped;
    }

    Vector3 normal;
    Vector3 surface_point;
    double depth = 0.0;
    if (!inside) {
        const Vector3 away = sphere.position - nearest;
        const double distance = length(away);
        if (distance >= radius + reach) return false;
        normal = away / distance;  // distance > 0 because the centre is outside the box
        surface_point = nearest;
        depth = radius - distance;
    } else {
        // The centre is inside: leave by the nearest face.
        std::size_t face = 0;
        for (std::size_t k = 1; k < 3; ++k)
            if (b.half[k] - std::abs(local[k]) < b.half[face] - std::abs(local[face])) face = k;
        const double side = local[face] >= 0.0 ? 1.0 : -1.0;
        normal = b.axis[face] * side;
        const double to_face = b.half[face] - std::abs(local[face]);
        surface_point = sphere.position + normal * to_face;
        depth = radius + to_face;
    }
    out.normal = normal;
    // Halfway between the box surface and the sphere's deepest point, surface - depth n.
    out.add_point(surface_point - normal * (depth / 2.0), depth);
    return true;
}

bool collide_box_box(const RigidBody& a, const RigidBody& b, Contact& out, double reach) {
    out = Contact{};
    const OrientedBox box_a = oriented_box(a);
    const OrientedBox box_b = oriented_box(b);
    Separation s;
    if (!least_overlap(box_a, box_b, reach, s)) return false;
    const double size = std::max(largest_half_extent(box_a), largest_half_extent(box_b));
    const double merge_distance = relative_tolerance * size;
    const double tie = relative_tolerance * size;  // least_overlap()'s
    const double touching = tolerances::resting_corner * size;

    out.normal = s.normal;
    if (s.kind == Separation::Kind::face_of_a)  // a's face towards b points along -normal
        clip_incident_face(box_a, s.index_a, -s.normal, box_b, s.normal, merge_distance, touching, reach, out);
    else if (s.kind == Separation::Kind::face_of_b)  // b's face towards a points along +normal
        clip_incident_face(box_b, s.index_b, s.normal, box_a, s.normal, merge_distance, touching, reach, out);
    else
        edge_contact(box_a, box_b, s, tie, out);
    if (out.point_count == 0) return false;  // a face overlap whose clipped face stays in front: only grazing
    out.penetration = std::max(out.penetration, s.overlap);
    return true;
}

bool collide_with_box(const RigidBody& a, std::uint32_t index_a, const RigidBody& b, std::uint32_t index_b,
                      Contact& out, double reach) {
    const ShapeKind ka = a.shape.kind;
    const ShapeKind kb = b.shape.kind;
    bool touching = false;
    if (ka == ShapeKind::box && kb == ShapeKind::box) {
        touching = collide_box_box(a, b, out, reach);
    } else if (ka == ShapeKind::box && kb == ShapeKind::plane) {
        touching = collide_box_plane(a, b, out, reach);
    } else if (ka == ShapeKind::plane && kb == ShapeKind::box) {
        touching = collide_box_plane(b, a, out, reach);
        std::swap(index_a, index_b);
    } else if (ka == ShapeKind::sphere && kb == ShapeKind::box) {
        touching = collide_sphere_box(a, b, out, reach);
    } else if (ka == ShapeKind::box && kb == ShapeKind::sphere) {
        touching = collide_sphere_box(b, a, out, reach);
        out.normal = -out.normal;  // computed from the box (a) towards the sphere (b)
    }
    if (!touching) return false;
    out.body1 = index_a;
    out.body2 = index_b;
    return true;
}

Vector3 nearest_point_on_box(const RigidBody& box, const Vector3& centre, const Vector3& point) {
    const Vector3 local = rotate(conjugate(box.orientation), point - centre);
    const Vector3& h = box.shape.half_extents;
    const Vector3 clamped{std::clamp(local.x, -h.x, h.x), std::clamp(local.y, -h.y, h.y), std::clamp(local.z, -h.z, h.z)};
    return centre + rotate(box.orientation, clamped);
}

}  // namespace workbook
