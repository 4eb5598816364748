#include "workbook/broad_phase.hpp"
#include "workbook/detection.hpp"
#include "workbook/tolerances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace workbook {

double bounding_radius(const RigidBody& body) {
    switch (body.shape.kind) {
        case ShapeKind::sphere: return body.shape.radius;
        case ShapeKind::box: return length(body.shape.half_extents);
        case ShapeKind::plane: break;
    }
    return std::numeric_limits<double>::infinity();
}

void ProxySet::add_plane(const RigidBody& body, std::uint32_t index) {
    const bool movable = !body.is_immovable();
    if (compact) {
        CellProxy& p = cells.emplace_back();
        p.index = index;
        p.movable = movable;
        p.plane = true;
    } else {
        GridProxy& p = proxies.emplace_back();
        p.index = index;
        p.movable = movable;
        p.plane = true;
    }
    planes.push_back({index, movable, body.position, rotate(body.orientation, body.shape.normal)});
}

void BroadPhase::all_pairs(std::span<const RigidBody> bodies, std::vector<BodyPair>& pairs, bool immovable_pairs) {
    pairs.clear();
    const auto count = static_cast<std::uint32_t>(bodies.size());
    for (std::uint32_t i = 0; i < count; ++i)
        for (std::uint32_t j = i + 1; j < count; ++j)
            if (immovable_pairs || !(bodies[i].is_immovable() && bodies[j].is_immovable())) pairs.push_back({i, j});
}

void BroadPhase::find_pairs(std::span<const RigidBody> bodies, std::vector<BodyPair>& pairs, bool immovable_pairs) {
    scratch_set_.clear(bodies.size());
    for (std::uint32_t i = 0; i < bodies.size(); ++i) scratch_set_.add(bodies[i], i);
    find_pairs(scratch_set_, pairs, immovable_pairs);
}

namespace {

/// Cells per axis for an extent, at least one; saturates instead of overflowing.
std::uint64_t cells_along(double extent, double cell) {
    const double n = extent / cell;
    return n < 1e15 ? static_cast<std::uint64_t>(n) + 1 : std::uint64_t{1} << 50;
}

/// Resizes `v` to `n`, growing its capacity geometrically: the sizes here change from step to
/// step, and an exact fit would allocate again at every new largest size.
template <class T>
void resize_with_room(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) v.reserve(std::max(n, 2 * v.capacity()));
    v.resize(n);
}

constexpr std::uint32_t not_in_grid = std::numeric_limits<std::uint32_t>::max();

/// A sphere the swept test traces: movable, and moved further than the smallest radius.
bool is_fast(const ProxySet& set, const GridProxy& p) {
    return set.swept && p.movable && p.sphere && p.travel > set.fast_travel;
}

/// Whether body k of the set (in set order) is movable.
bool movable(const ProxySet& set, std::size_t k) { return set.compact ? set.cells[k].movable : set.proxies[k].movable; }

/// Whether the swept test traces a proxy as the grid keeps it (never one of a set without it).
bool fast(const GridProxy& p) { return p.fast; }
bool fast(const CellProxy&) { return false; }

/// The proxy with its fast flag set, as the grid keeps it.
GridProxy with_fast_flag(const ProxySet& set, GridProxy p) {
    p.fast = is_fast(set, p);
    return p;
}

}  // namespace

void BroadPhase::find_pairs(const ProxySet& set, std::vector<BodyPair>& pairs, bool immovable_pairs, bool sorted) {
    pairs.clear();
    contact_keys_.clear();
    sweep_pairs_.clear();
    // Room for one pair per body from the start (a resting pile has about one, the gas of
    // bench/ a few hundredths): the counts change from step to step, and growing only when a
    // new largest count comes would allocate now and then long after the scene warmed up.
    const std::size_t count = set.size();
    if (contact_keys_.capacity() < count) contact_keys_.reserve(count);
    if (pairs.capacity() < count) pairs.reserve(count);
    if (set.swept && sweep_pairs_.capacity() < 2 * count) {
        sweep_pairs_.reserve(2 * count);
        sweep_partners_.reserve(2 * count);
    }
    has_grid_ = build_grid(set);
    if (!has_grid_) {
        // A body at NaN or infinity has no cell; testing every pair keeps the answer (no
        // contact with it) exactly what it would have been.
        for (std::uint32_t i = 0; i < count; ++i)
            for (std::uint32_t j = i + 1; j < count; ++j)
                if (immovable_pairs || movable(set, i) || movable(set, j)) pairs.push_back({i, j});
        sweep_start_.clear();
        return;
    }
    collect_pairs(set, immovable_pairs);
    finish(set, pairs, sorted);
}

bool BroadPhase::build_grid(const ProxySet& set) {
    if (!(set.poison == 0.0)) return false;
    const double lo[3] = {set.low.x, set.low.y, set.low.z};
    const double hi[3] = {set.high.x, set.high.y, set.high.z};
    const double largest = set.largest_radius;
    const std::size_t bounded = set.bounded;
    largest_radius_ = largest;
    margin_ = set.margin;

    // The swept test pairs bodies whose ends are within r_1 + t_1 + r_2 + t_2 of each other (t
    // the travel). Cells sized for the fastest sphere would grow with N (the fastest of a
    // larger gas is faster: 11.6 m/s of 1,000, 13.8 m/s of 100,000) and fill with pairs to
    // test, so they are sized for r + 2 t of the mean travel; the spheres that reach further
    // are "large" and look beyond their neighbouring cells for partners (in the gas 1 in 20).
    // A sphere that travelled more than four of the largest radii is "wide": it looks as far
    // as it must for partners, but the others do not look as far for it, as that would widen
    // the search of every large sphere (at N = 100,000 the gas has about 20, some 12 m/s fast;
    // tried against every body instead, they cost the step a fifth of its time).
    const double wide_travel = 4.0 * largest;
    wide_travel_ = wide_travel;
    double small_reach = largest;
    if (set.swept) {
        const double mean_travel = set.spheres > 0 ? set.travel_sum / static_cast<double>(set.spheres) : 0.0;
        small_reach = largest + 2.0 * mean_travel;
        const double scale = std::max({std::abs(lo[0]), std::abs(lo[1]), std::abs(lo[2]), std::abs(hi[0]),
                                       std::abs(hi[1]), std::abs(hi[2])});
        // Travels are lengths of differences of coordinates: a few ulps of them, with room to spare.
        slack_ = tolerances::travel_slack * (scale + largest + wide_travel);
    }
    // Two bodies pair within their radii and the margin (0 unless speculative contacts).
    const double reach = 2.0 * small_reach + set.margin;
    small_reach_ = small_reach;

    // Cells at least one largest reach wide (with room for rounding), so that two bodies that
    // may pair sit in the same or neighbouring cells, or half that with fine cells (two bodies
    // that may pair then sit at most two cells apart); coarser when the bodies are spread out,
    // so that the grid never has more than about two cells per body (memory stays linear in N),
    // or three where fine cells are asked for: with two, the bench's pile (event timing's
    // widened spheres) had cells 0.085 m wide where half its largest reach is 0.077 m, and its
    // walk tested (0.085 / 0.077)^3, a third, more pairs; with three they are 0.077 m wide, and
    // the pile's event step at N = 10,000 and 100,000 is about 4% faster.
    const std::size_t budget = (set.fine_cells ? 3 : 2) * bounded + 8;
    const double full = std::max(reach * (1.0 + tolerances::grid_cell_margin) + 4.0 * slack_, std::numeric_limits<double>::min());
    // Where the budget binds, start near the width that meets it (the volume, or area, or
    // length the bodies span over the budget), then widen in small steps: steps of 1.5 left
    // the 2D gas of 1,000 discs with cells 0.34 m wide where 0.23 m fit, twice the pairs to test.
    double span = 1.0;
    int dimensions = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (hi[axis] - lo[axis] > 0.0) {
            span *= hi[axis] - lo[axis];
            ++dimensions;
        }
    }
    const double least = dimensions > 0 ? 0.9 * std::pow(span / static_cast<double>(budget), 1.0 / dimensions) : 0.0;
    // Fine cells only for bodies spread in three dimensions, and where the budget lets them be
    // narrower than 0.6 of a reach, so that a cell and the two around it each way span less
    // than three cells of a reach. Walking five cells each way rather than three covers (5/6)^3
    // of the volume in 3D, (5/6)^2 in 2D, over four or eight times the cells: event timing's
    // step in the pile of the bench (3D) was 4 to 8% faster, in the gas (2D) 7% slower.
    near_cells_ = set.fine_cells && !set.swept && dimensions == 3 && 5.0 * least < 3.0 * full ? 2 : 1;
    double cell = std::max(full / static_cast<double>(near_cells_), least);
    std::uint64_t nx = 0, ny = 0, nz = 0;
    for (;;) {
        nx = cells_along(hi[0] - lo[0], cell);
        ny = cells_along(hi[1] - lo[1], cell);
        nz = cells_along(hi[2] - lo[2], cell);
        if (nx <= budget && ny <= budget && nz <= budget && nx * ny * nz <= budget) break;
        cell *= 1.05;
    }
    const double inverse_cell = 1.0 / cell;
    inverse_cell_ = inverse_cell;
    const std::uint64_t along_world[3] = {nx, ny, nz};
    lay_axes(set, lo, along_world);
    // How far apart in the cells' order two cells next to each other along x, y and z are.
    std::uint64_t stride[3];
    stride[axis_[0]] = 1, stride[axis_[1]] = cells_[0], stride[axis_[2]] = cells_[0] * cells_[1];
    const std::uint64_t stride_x = stride[0], stride_y = stride[1], stride_z = stride[2];
    auto axis_cell = [inverse_cell](double x, double low, std::uint64_t n) {
        return std::min(static_cast<std::uint64_t>((x - low) * inverse_cell), n - 1);
    };

    // Counting sort of the bounded proxies by cell.
    const std::size_t cells = nx * ny * nz;
    if (cell_start_.capacity() < budget + 1) cell_start_.reserve(budget + 1);  // the most cells there can be
    cell_start_.assign(cells + 1, 0);
    const std::size_t count = set.size();
    resize_with_room(cell_of_, count);
    resize_with_room(slot_of_, count);
    std::size_t in_grid = 0;
    const auto bin = [&](const auto& proxies) {
        for (std::size_t k = 0; k < count; ++k) {
            const auto& p = proxies[k];
            if (p.plane) {
                cell_of_[k] = not_in_grid;
                continue;
            }
            const std::uint64_t c = axis_cell(p.z, lo[2], nz) * stride_z + axis_cell(p.y, lo[1], ny) * stride_y +
                                    axis_cell(p.x, lo[0], nx) * stride_x;
            cell_of_[k] = static_cast<std::uint32_t>(c);
            ++cell_start_[c + 1];
            ++in_grid;
        }
    };
    if (set.compact) bin(set.cells);
    else bin(set.proxies);
    for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
    // A set without the swept test needs only the compact copies (CellProxy).
    small_cells_ = !set.swept;
    if (small_cells_) resize_with_room(small_by_cell_, in_grid);
    else resize_with_room(by_cell_, in_grid);
    // Copies, not indices: the walk below then reads memory in order (at N = 100,000 the
    // indirection through an index array made the pass 1.6 times slower). cell_start_[c] walks
    // forward while filling; afterwards cell c spans [old start of c, start of c + 1).
    large_.clear();
    wide_.clear();
    // Room for every proxy (4 bytes each): how many are large changes from step to step.
    if (large_.capacity() < in_grid) large_.reserve(in_grid);
    if (wide_.capacity() < in_grid) wide_.reserve(in_grid);
    largest_reach_ = largest;
    for (std::size_t k = 0; k < count; ++k) {
        if (cell_of_[k] == not_in_grid) continue;
        const std::uint32_t slot = cell_start_[cell_of_[k]]++;
        slot_of_[k] = slot;
        if (set.compact) {  // gathered as the grid keeps it (a compact set has no swept test)
            small_by_cell_[slot] = set.cells[k];
            continue;
        }
        const GridProxy& p = set.proxies[k];
        if (small_cells_) {
            small_by_cell_[slot] = {p.x, p.y, p.z, p.radius, p.index, p.movable, false};
            continue;
        }
        by_cell_[slot] = with_fast_flag(set, p);
        const double own_reach = p.radius + p.travel;
        // A wide sphere is large too, whatever its reach: it makes its own search, and nobody
        // else's search takes it in (is_large() below), so that each pair is met once.
        if (!(own_reach <= small_reach) || is_wide(p)) large_.push_back(slot);  // NaN too
        if (is_wide(p)) {
            wide_.push_back(slot);
            continue;
        }
        largest_reach_ = std::max(largest_reach_, own_reach);
    }
    for (std::size_t c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
    cell_start_[0] = 0;
    return true;
}

namespace {

/// Along each world axis, how many of a sample of a compact set's bodies (every seventh, or
/// about a thousand spread over a larger set) lie further from the body gathered before them
/// than their own radius; none for a set that is not compact. A sample, not every body: with a
/// count at every body as it was gathered, the gas of the bench at N = 10,000 measured about 1%
/// slower (near the noise), and every seventh body of the pile at N = 100,000 was half a percent
/// of its event step, each read missing the caches.
void count_jumps(const ProxySet& set, std::uint32_t (&jumps)[3]) {
    jumps[0] = jumps[1] = jumps[2] = 0;
    if (!set.compact) return;
    constexpr std::size_t most_samples = 1024;
    // Odd, so as not to fall in step with rows of a power of two.
    const std::size_t stride = std::max<std::size_t>(7, set.cells.size() / most_samples) | 1;
    for (std::size_t k = stride; k < set.cells.size(); k += stride) {
        const CellProxy& p = set.cells[k];
        const CellProxy& before = set.cells[k - 1];
        if (p.plane || before.plane) continue;
        jumps[0] += std::abs(p.x - before.x) > p.radius ? 1u : 0u;  // (a NaN counts as no jump)
        jumps[1] += std::abs(p.y - before.y) > p.radius ? 1u : 0u;
        jumps[2] += std::abs(p.z - before.z) > p.radius ? 1u : 0u;
    }
}

}  // namespace

void BroadPhase::lay_axes(const ProxySet& set, const double (&low)[3], const std::uint64_t (&cells)[3]) {
    // Why in the order the bodies come: the grid's cells are binned body after body, and the
    // passes after its walk (event timing's boxes, candidate lists and first times of impact)
    // read each pair's two bodies from arrays by body, in the order the walk finds them. When
    // consecutive bodies sit in consecutive cells, both go through memory nearly in order;
    // otherwise each row of cells jumps between distant bodies. The bench's pile numbers its
    // balls along x, then z, then up y, where the world's order lays layers along z: its
    // event-timed step at N = 100,000 was 3 to 4% slower that way. The axis along which the
    // bodies jump most runs along the rows, the one along which they jump least across the
    // layers. An axis goes before another only where the bodies jump at least twice as often
    // along it, else the world's order stays: as often says nothing of the order they come in
    // (the gas of the bench, whose discs fly every way, jumps along x and y about as often, and
    // the sample then laid its rows along y in some steps). Only a compact set's grid (event
    // timing's) is laid so: the swept test's search of large spheres reads the grid along the
    // world's axes.
    std::uint32_t jumps[3];
    count_jumps(set, jumps);
    axis_[0] = 0, axis_[1] = 1, axis_[2] = 2;
    // An insertion sort of the three: std::stable_sort may take a buffer from the heap, and a
    // warm step allocates nothing.
    const auto more_jumps = [&jumps](int a, int b) { return jumps[a] > 2 * std::uint64_t{jumps[b]}; };
    for (int a = 1; a < 3; ++a)
        for (int b = a; b > 0 && more_jumps(axis_[b], axis_[b - 1]); --b) std::swap(axis_[b], axis_[b - 1]);
    for (int g = 0; g < 3; ++g) {
        low_[g] = low[axis_[g]];
        cells_[g] = cells[axis_[g]];
    }
}

void BroadPhase::collect_pairs(const ProxySet& set, bool immovable_pairs) {
    const double slack = slack_;
    const double margin = margin_;
    // The pair's tests: bounding spheres overlap (for the narrow phase), and, for the swept
    // test, paths may meet (a sphere's path lies within its travel of its end). The travel is 0
    // for every body the swept test leaves alone, so the wider reach holds both, and most
    // pairs stop at the first comparison.
    auto pair = [&](const GridProxy& p, const GridProxy& q) {
        const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
        const double d2 = dx * dx + dy * dy + dz * dz;
        const double radii = p.radius + q.radius + margin;
        const double reach = (radii + p.travel + q.travel) * (1.0 + tolerances::may_touch_slack) + slack;
        if (d2 > reach * reach) return;
        // Speculative contacts also reach as far as the two travelled (within `reach` above;
        // planes are not in the grid). Conservative by a relative slack, so rounding here never
        // drops a pair the narrow phase would keep.
        const double contact = p.radius + q.radius + speculative_reach(margin, p.travel, q.travel);
        if (d2 <= contact * contact * (1.0 + tolerances::conservative_slack) && (immovable_pairs || p.movable || q.movable)) {
            const std::uint64_t a = std::min(p.index, q.index), b = std::max(p.index, q.index);
            contact_keys_.push_back(a << 32 | b);
        }
        if (p.sphere && q.sphere && (p.fast || q.fast)) {
            // Asked here, while both are at hand, rather than by the swept test from scattered memory.
            const bool may = spheres_may_touch({p.x, p.y, p.z}, p.start, p.radius, {q.x, q.y, q.z}, q.start, q.radius);
            const std::uint32_t flag = may ? partner_may_touch : 0;
            if (p.fast) sweep_pairs_.push_back({p.index, q.index | flag});
            if (q.fast) sweep_pairs_.push_back({q.index, p.index | flag});
        } else if (p.fast && !q.sphere) {
            sweep_pairs_.push_back({p.index, q.index | partner_may_touch});  // a box: the swept test decides
        } else if (q.fast && !p.sphere) {
            sweep_pairs_.push_back({q.index, p.index | partner_may_touch});
        }
    };

    // Each cell against itself and the neighbours after it: in its own row the next cell, in
    // the next row the three below it, in the next layer the nine behind it (with fine cells,
    // two cells each way: the next two in its row, five in each of the next two rows, five
    // rows of five in each of the next two layers). The cells of a row are contiguous in
    // by_cell_, so each row's part is one range.
    const std::uint64_t nx = cells_[0], ny = cells_[1], nz = cells_[2];
    const std::uint64_t around = near_cells_;
    const std::uint32_t* start = cell_start_.data();
    const GridProxy* proxies = by_cell_.data();
    auto walk = [&](const auto* cells, auto&& test) {
        for (std::uint64_t z = 0; z < nz; ++z) {
            for (std::uint64_t y = 0; y < ny; ++y) {
                const std::uint64_t row = (z * ny + y) * nx;
                if (start[row] == start[row + nx]) continue;  // an empty row
                for (std::uint64_t x = 0; x < nx; ++x) {
                    const std::uint32_t begin = start[row + x], end = start[row + x + 1];
                    if (begin == end) continue;
                    const std::uint64_t x0 = x > around ? x - around : 0, x1 = std::min(x + around, nx - 1);
                    std::uint32_t ranges[12][2];  // at most 2 + 2 * 5 with fine cells
                    int count = 0;
                    for (std::uint64_t yy = y + 1; yy <= std::min(y + around, ny - 1); ++yy) {
                        const std::uint64_t next = (z * ny + yy) * nx;
                        ranges[count][0] = start[next + x0], ranges[count][1] = start[next + x1 + 1], ++count;
                    }
                    for (std::uint64_t zz = z + 1; zz <= std::min(z + around, nz - 1); ++zz) {
                        for (std::uint64_t yy = y > around ? y - around : 0; yy <= std::min(y + around, ny - 1); ++yy) {
                            const std::uint64_t next = (zz * ny + yy) * nx;
                            ranges[count][0] = start[next + x0], ranges[count][1] = start[next + x1 + 1], ++count;
                        }
                    }
                    const std::uint32_t own_end = start[row + x1 + 1];
                    for (std::uint32_t s = begin; s < end; ++s) {
                        const auto& p = cells[s];
                        for (std::uint32_t t = s + 1; t < own_end; ++t) test(p, cells[t]);
                        for (int r = 0; r < count; ++r)
                            for (std::uint32_t t = ranges[r][0]; t < ranges[r][1]; ++t) test(p, cells[t]);
                    }
                }
            }
        }
    };
    if (set.swept) {
        walk(proxies, pair);
    } else {
        // Without a swept set every travel is 0 and no sphere is fast, and pair() comes down to
        // its second test (the first, wider by a relative slack, passes whenever it does):
        // that test alone, within the margin of speculative contacts (0 under event timing), as
        // event timing's widened spheres and worlds without the swept test ask. Over the compact
        // copies, which hold all it reads.
        walk(small_by_cell_.data(), [&](const CellProxy& p, const CellProxy& q) {
            const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
            const double d2 = dx * dx + dy * dy + dz * dz;
            const double radii = p.radius + q.radius + margin;
            if (d2 <= radii * radii * (1.0 + tolerances::conservative_slack) && (immovable_pairs || p.movable || q.movable)) {
                const std::uint64_t a = std::min(p.index, q.index), b = std::max(p.index, q.index);
                contact_keys_.push_back(a << 32 | b);
            }
        });
    }

    auto is_large = [this](const GridProxy& q) { return !(q.radius + q.travel <= small_reach_) || is_wide(q); };
    // Large spheres against the cells beyond their neighbours, as far as a partner may be: its
    // own reach and the largest of any sphere that is not wide. A pair of two large spheres that
    // are not wide is tried from the one of smaller index (each one's search holds the other); a
    // wide partner is left to its own search, and two wide ones meet in the loop after this.
    for (const std::uint32_t s : large_) {
        const GridProxy& p = proxies[s];
        const bool p_wide = is_wide(p);
        const double far = ((p.radius + p.travel + largest_reach_ + margin) * (1.0 + tolerances::may_touch_slack) + slack) * inverse_cell_ *
                           (1.0 + tolerances::conservative_slack);
        const std::uint64_t k = far < 1e15 ? static_cast<std::uint64_t>(far) + 1 : std::uint64_t{1} << 50;
        const std::uint64_t cx = axis_cell_of(p.x, 0), cy = axis_cell_of(p.y, 1), cz = axis_cell_of(p.z, 2);
        auto low_end = [k](std::uint64_t c) { return c > k ? c - k : 0; };
        const std::uint64_t x0 = low_end(cx), x1 = std::min(cx + k, nx - 1);
        for (std::uint64_t z = low_end(cz); z <= std::min(cz + k, nz - 1); ++z) {
            for (std::uint64_t y = low_end(cy); y <= std::min(cy + k, ny - 1); ++y) {
                const std::uint64_t row = (z * ny + y) * nx;
                auto scan = [&](std::uint64_t from, std::uint64_t to) {  // cells [from, to] of the row
                    for (std::uint32_t t = start[row + from]; t < start[row + to + 1]; ++t) {
                        const GridProxy& q = proxies[t];
                        if (!is_large(q) || (p_wide && !is_wide(q)) || (!is_wide(q) && p.index < q.index)) pair(p, q);
                    }
                };
                const bool near = (z + 1 >= cz && z <= cz + 1) && (y + 1 >= cy && y <= cy + 1);
                if (!near) {
                    scan(x0, x1);
                    continue;
                }
                // The neighbouring cells were walked above.
                if (cx >= x0 + 2) scan(x0, cx - 2);
                if (cx + 2 <= x1) scan(cx + 2, x1);
            }
        }
    }

    // Pairs of wide spheres (a handful), except those in neighbouring cells, walked above.
    for (std::size_t a = 0; a < wide_.size(); ++a) {
        const GridProxy& p = proxies[wide_[a]];
        const std::uint64_t px = axis_cell_of(p.x, 0), py = axis_cell_of(p.y, 1), pz = axis_cell_of(p.z, 2);
        for (std::size_t b = a + 1; b < wide_.size(); ++b) {
            const GridProxy& q = proxies[wide_[b]];
            auto near = [](std::uint64_t u, std::uint64_t v) { return u + 1 >= v && v + 1 >= u; };
            if (near(px, axis_cell_of(q.x, 0)) && near(py, axis_cell_of(q.y, 1)) && near(pz, axis_cell_of(q.z, 2))) continue;
            pair(p, q);
        }
    }
    collect_plane_pairs(set, immovable_pairs);
}

void BroadPhase::collect_plane_pairs(const ProxySet& set, bool immovable_pairs) {
    auto test = [&](const auto& p, const PlaneProxy& u) {
        // The height of the centre above the plane, as the narrow phase computes it.
        const Vector3 offset{p.x - u.point.x, p.y - u.point.y, p.z - u.point.z};
        const double height = dot(offset, u.normal);
        // A relative slack keeps the test conservative.
        const double radius = p.radius + margin_;
        if ((immovable_pairs || p.movable || u.movable) && height < radius + tolerances::conservative_slack * (radius + std::abs(height))) {
            const std::uint64_t a = std::min(p.index, u.index), b = std::max(p.index, u.index);
            contact_keys_.push_back(a << 32 | b);
        }
        // The swept test's own condition for a plane (swept_spheres.cpp): the centre ended
        // behind it. Written as its negation so that a NaN is kept, as it is there.
        if (fast(p) && !((height - p.radius) + p.radius >= 0.0)) sweep_pairs_.push_back({p.index, u.index | partner_may_touch});
    };
    const std::uint64_t nx = cells_[0], ny = cells_[1], nz = cells_[2];
    const double cell = 1.0 / inverse_cell_;
    for (const PlaneProxy& u : set.planes) {
        // Only the cells that come near the plane: along a row of cells the height of a cell's
        // centre grows by n_x * cell from one cell to the next, and no point of a cell lies lower
        // than its centre's height minus (|n_x| + |n_y| + |n_z|) cell / 2. A cell whose lowest
        // point is above every radius (with a cell to spare for rounding) holds no pair.
        // The plane's point and normal along the grid's axes, the row's first: x, y and z here
        // and below are the grid's.
        const double point_along[3] = {u.point.x, u.point.y, u.point.z};
        const double normal_along[3] = {u.normal.x, u.normal.y, u.normal.z};
        const Vector3 point{point_along[axis_[0]], point_along[axis_[1]], point_along[axis_[2]]};
        const Vector3 n{normal_along[axis_[0]], normal_along[axis_[1]], normal_along[axis_[2]]};
        const double half_spread = 0.5 * cell * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
        const double reach = largest_radius_ + margin_ + half_spread + cell;
        for (std::uint64_t z = 0; z < nz; ++z) {
            for (std::uint64_t y = 0; y < ny; ++y) {
                const std::uint64_t row = (z * ny + y) * nx;
                if (cell_start_[row] == cell_start_[row + nx]) continue;
                // Height of the centre of the row's cell x = 0, then per cell along x.
                const Vector3 first{low_[0] + 0.5 * cell - point.x, low_[1] + (static_cast<double>(y) + 0.5) * cell - point.y,
                                    low_[2] + (static_cast<double>(z) + 0.5) * cell - point.z};
                const double h0 = dot(first, n), step = n.x * cell;
                std::uint64_t x0 = 0, x1 = nx - 1;
                // Cells with h0 + step * x <= reach: a ray of x, clamped to the row.
                if (step > 0.0) {
                    const double last = (reach - h0) / step;
                    if (!(last >= 0.0)) continue;
                    if (last < static_cast<double>(nx - 1)) x1 = static_cast<std::uint64_t>(last);
                } else if (step < 0.0) {
                    const double first_x = (reach - h0) / step;
                    if (first_x > static_cast<double>(nx - 1)) continue;
                    if (first_x > 0.0) x0 = static_cast<std::uint64_t>(std::ceil(first_x));
                } else if (!(h0 <= reach)) {
                    continue;
                }
                for (std::uint32_t s = cell_start_[row + x0]; s < cell_start_[row + x1 + 1]; ++s) {
                    if (small_cells_) test(small_by_cell_[s], u);
                    else test(by_cell_[s], u);
                }
            }
        }
    }
}

void BroadPhase::finish(const ProxySet& set, std::vector<BodyPair>& pairs, bool sorted) {
    if (sorted) std::sort(contact_keys_.begin(), contact_keys_.end());
    resize_with_room(pairs, contact_keys_.size());
    for (std::size_t k = 0; k < contact_keys_.size(); ++k)
        pairs[k] = {static_cast<std::uint32_t>(contact_keys_[k] >> 32), static_cast<std::uint32_t>(contact_keys_[k])};

    if (!set.swept) {
        sweep_start_.clear();
        return;
    }
    // Each fast sphere's partners, as lists by body (a counting sort of the pairs).
    const std::size_t count = set.proxies.size();
    resize_with_room(sweep_start_, count + 1);
    std::fill(sweep_start_.begin(), sweep_start_.end(), 0);
    for (const BodyPair& p : sweep_pairs_) ++sweep_start_[p.first + 1];
    for (std::size_t i = 0; i < count; ++i) sweep_start_[i + 1] += sweep_start_[i];
    resize_with_room(sweep_partners_, sweep_start_[count]);
    for (const BodyPair& p : sweep_pairs_) sweep_partners_[sweep_start_[p.first]++] = p.second;
    for (std::size_t i = count; i > 0; --i) sweep_start_[i] = sweep_start_[i - 1];
    sweep_start_[0] = 0;
}

void BroadPhase::widen(ProxySet& set, std::uint32_t index, double radius) {
    double& gathered = set.compact ? set.cells[index].radius : set.proxies[index].radius;
    gathered = std::max(gathered, radius);
    if (!has_grid_ || cell_of_[index] == not_in_grid) return;
    const std::uint32_t slot = slot_of_[index];
    if (small_cells_) small_by_cell_[slot].radius = std::max(small_by_cell_[slot].radius, radius);
    else by_cell_[slot].radius = std::max(by_cell_[slot].radius, radius);
    // bodies_near() looks as far as the widest proxy in the grid.
    largest_radius_ = std::max(largest_radius_, radius);
}

void BroadPhase::bodies_near(const ProxySet& set, const Vector3& centre, double radius,
                             std::vector<std::uint32_t>& out, const Vector3& box) const {
    // The caller's box, with room for rounding (a NaN side, which narrows nothing, stays NaN:
    // the tests below keep a body unless it is certainly outside).
    constexpr double room = (1.0 + tolerances::conservative_slack) * (1.0 + tolerances::conservative_slack);
    const double box_half[3] = {box.x * room, box.y * room, box.z * room};
    const auto near = [&](const auto& q) {
        const double within = (radius + q.radius) * (1.0 + tolerances::conservative_slack);
        const double dx = q.x - centre.x, dy = q.y - centre.y, dz = q.z - centre.z;
        // Outside the box along an axis: left out here rather than by the caller, which would
        // read more of it to find so (in the bench's pile, the balls beside a ball).
        const bool outside =
            std::abs(dx) > box_half[0] || std::abs(dy) > box_half[1] || std::abs(dz) > box_half[2];
        return dx * dx + dy * dy + dz * dz <= within * within && !outside;
    };
    for (const PlaneProxy& plane : set.planes)
        if (dot(centre - plane.point, plane.normal) <= radius * (1.0 + tolerances::conservative_slack)) out.push_back(plane.index);
    if (!has_grid_) {
        const auto every = [&](const auto& proxies) {
            for (const auto& q : proxies)
                if (!q.plane && near(q)) out.push_back(q.index);
        };
        if (set.compact) every(set.cells);
        else every(set.proxies);
        return;
    }
    // Every proxy in the grid is at most largest_radius_ wide, so one within reach has its
    // centre within radius + largest_radius_ of `centre` along each axis: the cells that
    // interval covers, binned as build_grid() bins a centre. (Rounding is monotone, so a centre
    // inside the interval falls in a cell inside the range; the second slack covers the
    // rounding of near()'s own sum of squares.) The interval, not the whole cells around the
    // centre's cell: for a reach of about a cell that is 27 to 64 cells instead of 125.
    const double centre_along[3] = {centre.x, centre.y, centre.z};
    const double far = (radius + largest_radius_) * (1.0 + tolerances::conservative_slack) * (1.0 + tolerances::conservative_slack);
    // The caller's box where it is narrower (std::min keeps `far` for a NaN side).
    std::uint64_t from[3], to[3];
    for (int g = 0; g < 3; ++g) {  // along the grid's axes, the row's first
        const double c = centre_along[axis_[g]];
        const double half = std::min(far, box_half[axis_[g]]);
        // The range of cells in doubles first: a centre outside the grid has a negative index.
        const double lo = std::floor((c - half - low_[g]) * inverse_cell_);
        const double hi = std::floor((c + half - low_[g]) * inverse_cell_);
        const double last = static_cast<double>(cells_[g] - 1);
        if (!(hi >= 0.0 && lo <= last)) return;  // (also for a NaN centre)
        from[g] = static_cast<std::uint64_t>(std::clamp(lo, 0.0, last));
        to[g] = static_cast<std::uint64_t>(std::clamp(hi, 0.0, last));
    }
    const std::uint64_t nx = cells_[0], ny = cells_[1];
    for (std::uint64_t z = from[2]; z <= to[2]; ++z)
        for (std::uint64_t y = from[1]; y <= to[1]; ++y) {
            const std::uint64_t row = (z * ny + y) * nx;
            for (std::uint32_t t = cell_start_[row + from[0]]; t < cell_start_[row + to[0] + 1]; ++t) {
                if (small_cells_) {
                    if (near(small_by_cell_[t])) out.push_back(small_by_cell_[t].index);
                } else if (near(by_cell_[t])) {
                    out.push_back(by_cell_[t].index);
                }
            }
        }
}

}  // namespace workbook
