#include "workbook/broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace workbook {

double bounding_radius(const RigidBody& body) {
    switch (body.shape.kind) {
        case ShapeKind::sphere: return body.shape.radius;
        case ShapeKind::box: return length(body.shape.half_extents);
        case ShapeKind::plane: break;
    }
    return std::numeric_limits<double>::infinity();
}

void BroadPhase::all_pairs(std::span<const RigidBody> bodies, std::vector<BodyPair>& pairs, bool immovable_pairs) {
    pairs.clear();
    const auto count = static_cast<std::uint32_t>(bodies.size());
    for (std::uint32_t i = 0; i < count; ++i)
        for (std::uint32_t j = i + 1; j < count; ++j)
            if (immovable_pairs || !(bodies[i].is_immovable() && bodies[j].is_immovable())) pairs.push_back({i, j});
}

namespace {

/// Cells per axis for an extent, at least one; saturates instead of overflowing.
std::uint64_t cells_along(double extent, double cell) {
    const double n = extent / cell;
    return n < 1e15 ? static_cast<std::uint64_t>(n) + 1 : std::uint64_t{1} << 50;
}

}  // namespace

void BroadPhase::find_pairs(std::span<const RigidBody> bodies, std::vector<BodyPair>& pairs, bool immovable_pairs) {
    pairs.clear();
    proxies_.clear();
    unbounded_.clear();
    plane_normals_.clear();
    double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[3] = {-lo[0], -lo[1], -lo[2]};
    double largest = 0.0;
    bool finite = true;
    const auto count = static_cast<std::uint32_t>(bodies.size());
    for (std::uint32_t i = 0; i < count; ++i) {
        const RigidBody& body = bodies[i];
        if (body.shape.kind == ShapeKind::plane) {
            unbounded_.push_back(i);
            plane_normals_.push_back(rotate(body.orientation, body.shape.normal));
            continue;
        }
        const Proxy p{body.position.x, body.position.y, body.position.z, bounding_radius(body), i, !body.is_immovable()};
        finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.radius);
        lo[0] = std::min(lo[0], p.x), hi[0] = std::max(hi[0], p.x);
        lo[1] = std::min(lo[1], p.y), hi[1] = std::max(hi[1], p.y);
        lo[2] = std::min(lo[2], p.z), hi[2] = std::max(hi[2], p.z);
        largest = std::max(largest, p.radius);
        proxies_.push_back(p);
    }
    // A body at NaN or infinity has no cell; testing every pair keeps the answer (no
    // contact with it) exactly what it would have been.
    if (!finite) {
        all_pairs(bodies, pairs, immovable_pairs);
        return;
    }

    // Cells at least one largest diameter wide, so that two overlapping bodies sit in the
    // same or neighbouring cells; coarser when the bodies are spread out, so that the grid
    // never has more than about two cells per body (memory stays linear in N).
    const std::size_t budget = 2 * proxies_.size() + 8;
    double cell = std::max(2.0 * largest, std::numeric_limits<double>::min()) * (1.0 + 1e-9);
    std::uint64_t nx = 0, ny = 0, nz = 0;
    for (;;) {
        nx = cells_along(hi[0] - lo[0], cell);
        ny = cells_along(hi[1] - lo[1], cell);
        nz = cells_along(hi[2] - lo[2], cell);
        if (nx <= budget && ny <= budget && nz <= budget && nx * ny * nz <= budget) break;
        cell *= 1.5;
    }
    const double inverse_cell = 1.0 / cell;
    auto axis_cell = [inverse_cell](double x, double low, std::uint64_t n) {
        return std::min(static_cast<std::uint64_t>((x - low) * inverse_cell), n - 1);
    };

    // Counting sort of the proxies by cell: entries of a cell keep index order.
    const std::size_t cells = nx * ny * nz;
    cell_start_.assign(cells + 1, 0);
    cell_of_.resize(proxies_.size());
    for (std::size_t k = 0; k < proxies_.size(); ++k) {
        const Proxy& p = proxies_[k];
        const std::uint64_t c = (axis_cell(p.z, lo[2], nz) * ny + axis_cell(p.y, lo[1], ny)) * nx + axis_cell(p.x, lo[0], nx);
        cell_of_[k] = static_cast<std::uint32_t>(c);
        ++cell_start_[c + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
    by_cell_.resize(proxies_.size());
    {
        // Copies, not indices: the neighbour scans below then read memory in order (at
        // N = 100,000 the indirection through an index array made find_pairs 1.6 times slower).
        // cell_start_[c] walks forward while filling; afterwards cell c spans
        // [cell_start_[c] - size, cell_start_[c]) = [old start of c, start of c + 1).
        for (std::size_t k = 0; k < proxies_.size(); ++k) by_cell_[cell_start_[cell_of_[k]]++] = proxies_[k];
        for (std::size_t c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
        cell_start_[0] = 0;
    }

    // Every body in index order: its partners of larger index, sorted, so that the pairs
    // come out in the order testing all pairs would visit them.
    std::size_t next_proxy = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        candidates_.clear();
        const bool i_movable = !bodies[i].is_immovable();
        if (bodies[i].shape.kind == ShapeKind::plane) {
            // A plane is unbounded: every later body may touch it.
            for (std::uint32_t j = i + 1; j < count; ++j)
                if (immovable_pairs || i_movable || !bodies[j].is_immovable()) pairs.push_back({i, j});
            continue;
        }
        const std::size_t k = next_proxy++;
        const Proxy& p = proxies_[k];
        const std::uint64_t cx = axis_cell(p.x, lo[0], nx), cy = axis_cell(p.y, lo[1], ny), cz = axis_cell(p.z, lo[2], nz);
        for (std::uint64_t z = cz > 0 ? cz - 1 : 0; z <= std::min(cz + 1, nz - 1); ++z) {
            for (std::uint64_t y = cy > 0 ? cy - 1 : 0; y <= std::min(cy + 1, ny - 1); ++y) {
                const std::uint64_t row = (z * ny + y) * nx;
                const std::uint64_t first = row + (cx > 0 ? cx - 1 : 0);
                const std::uint64_t last = row + std::min(cx + 1, nx - 1);
                // The cells of one row are contiguous in by_cell_: one range, no per-cell loop.
                for (std::uint32_t s = cell_start_[first]; s < cell_start_[last + 1]; ++s) {
                    const Proxy& q = by_cell_[s];
                    if (q.index <= i) continue;
                    if (!immovable_pairs && !p.movable && !q.movable) continue;
                    const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
                    const double reach = p.radius + q.radius;
                    // Conservative by a relative 1e-9, so rounding here never drops a pair
                    // the narrow phase would keep.
                    if (dx * dx + dy * dy + dz * dz <= reach * reach * (1.0 + 1e-9)) candidates_.push_back(q.index);
                }
            }
        }
        for (std::size_t u = 0; u < unbounded_.size(); ++u) {
            const std::uint32_t j = unbounded_[u];
            if (j < i || (!immovable_pairs && !i_movable && bodies[j].is_immovable())) continue;
            // The height of the centre above the plane, as the narrow phase computes it; a
            // relative 1e-9 of slack keeps the test conservative.
            const Vector3 offset{p.x - bodies[j].position.x, p.y - bodies[j].position.y, p.z - bodies[j].position.z};
            const double height = dot(offset, plane_normals_[u]);
            if (height < p.radius + 1e-9 * (p.radius + std::abs(height))) candidates_.push_back(j);
        }
        // Usually a handful: insertion sort beats std::sort's set-up here.
        for (std::size_t a = 1; a < candidates_.size(); ++a) {
            const std::uint32_t value = candidates_[a];
            std::size_t b = a;
            for (; b > 0 && candidates_[b - 1] > value; --b) candidates_[b] = candidates_[b - 1];
            candidates_[b] = value;
        }
        for (std::uint32_t j : candidates_) pairs.push_back({i, j});
    }
}

}  // namespace workbook
