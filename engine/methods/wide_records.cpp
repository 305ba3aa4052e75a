#include "methods/wide_records.hpp"

#include "derivation/contact_velocity.hpp"
#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <type_traits>

namespace impulse {

namespace {

constexpr std::uint32_t no_row = std::numeric_limits<std::uint32_t>::max();

// A record's bodies' velocities, lane by lane: body 0 and body 1 of each pair.
struct Velocities {
    Vec3x4 v[2], w[2];
};

void set_lane(Vec3x4& to, int lane, const Vec3& from) {
    for (int k = 0; k < 3; ++k) to.v[k][lane] = static_cast<float>(from[k]);
}

// Whether two matrices' lane `lane` have the same bits: equal, and -0 is not 0 (a NaN is never the same). (The
// WebAssembly build's library has no std::bit_cast.)
bool same_lane(const Mat3x4& a, const Mat3x4& b, int lane) {
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) {
            const float x = a.column[c].v[k][lane], y = b.column[c].v[k][lane];
            if (!(x == y && std::signbit(x) == std::signbit(y))) return false;
        }
    return true;
}

Axes lane_of(const AxesOf<Float4>& a, int lane) {
    return {a.n[lane], a.t1[lane], a.t2[lane]};
}

template <typename Body>
IMPULSE_KERNEL const Body& body_of(const RecordX4& record, int side, int lane, const Body* bodies, std::size_t none) {
    const int b = record.body[side][lane];
    return bodies[b < 0 ? none : static_cast<std::size_t>(b)];
}

template <typename Body>
IMPULSE_KERNEL Velocities gather(const RecordX4& record, const Body* bodies, std::size_t none) {
    Velocities s;
    for (int side = 0; side < 2; ++side)
        for (int lane = 0; lane < 4; ++lane) {
            const Body& body = body_of(record, side, lane, bodies, none);
            for (int k = 0; k < 3; ++k) {
                s.v[side].v[k][lane] = body.velocity[k];
                s.w[side].v[k][lane] = body.angular_velocity[k];
            }
        }
    return s;
}

template <typename Body>
IMPULSE_KERNEL void scatter(const RecordX4& record, Body* bodies, const Velocities& s) {
    for (int side = 0; side < 2; ++side)
        for (int lane = 0; lane < 4; ++lane) {
            const int b = record.body[side][lane];
            if (b < 0) continue;
            Body& body = bodies[static_cast<std::size_t>(b)];
            for (int k = 0; k < 3; ++k) {
                body.velocity[k] = s.v[side].v[k][lane];
                body.angular_velocity[k] = s.w[side].v[k][lane];
            }
        }
}

// Step 4 (contact_rows.hpp's row_velocity, lane by lane): body 0's point velocity less body 1's, in the contact's
// axes.
IMPULSE_KERNEL AxesOf<Float4> contact_velocity(const Velocities& s, const PointX4& point, const Mat3x4& basis) {
    const Vec3x4 p0 = point_velocity_of<Vec3x4>(s.v[0], s.w[0], point.anchor[0]);
    const Vec3x4 p1 = point_velocity_of<Vec3x4>(s.v[1], s.w[1], point.anchor[1]);
    const Vec3x4 v = transposed_times(basis, Vec3x4{p0.x() - p1.x(), p0.y() - p1.y(), p0.z() - p1.z()});
    return {v.x(), v.y(), v.z()};
}

// The contact-axes impulse `a` in world coordinates, g = C a (contact_rows.hpp's world_impulse, lane by lane).
IMPULSE_KERNEL Vec3x4 world_impulse(const Mat3x4& basis, const AxesOf<Float4>& a) {
    return times(basis, Vec3x4{a.n, a.t1, a.t2});
}

// Step 7 (contact_rows.hpp's apply_impulse, lane by lane): the contact-axes impulse `a` as g = C a, +g to body 0 at
// its anchor and -g to body 1 at its.
IMPULSE_KERNEL void apply(const RecordX4& record, const PointX4& point, const Mat3x4& basis, Velocities& s,
                          const AxesOf<Float4>& a) {
    const Vec3x4 impulse = world_impulse(basis, a);
    const Vec3x4 opposite{-impulse.x(), -impulse.y(), -impulse.z()};
    for (int side = 0; side < 2; ++side) {
        const BodyVelocityChangeOf<Vec3x4> c =
            body_velocity_change_of<Vec3x4>(side == 0 ? impulse : opposite, point.anchor[side],
                                            record.inverse_mass[side], record.inverse_inertia[side]);
        for (int k = 0; k < 3; ++k) {
            s.v[side].v[k] += c.velocity_change.v[k];
            s.w[side].v[k] += c.rotation_change.v[k];
        }
    }
}

// Keeps lambda_n in the point's largest lambda_n if it is larger (std::max's choice, lane by lane).
IMPULSE_KERNEL void keep_most_pushed(PointX4& point, Float4 n) {
    point.most_pushed = select(point.most_pushed < n, n, point.most_pushed);
}

// Keeps `after` as the point's total and its largest lambda_n.
IMPULSE_KERNEL void keep_total(PointX4& point, const AxesOf<Float4>& after) {
    point.total.n = after.n;
    point.total.t1 = after.t1;
    point.total.t2 = after.t2;
    keep_most_pushed(point, after.n);
}

}  // namespace

WideSoftness::WideSoftness(const Softness& s, double max_push, double h)
    : bias_rate(splat<Float4>(s.bias_rate)),
      mass_scale(splat<Float4>(s.mass_scale)),
      impulse_scale(splat<Float4>(s.impulse_scale)),
      max_push_velocity(splat<Float4>(max_push)),
      substep(splat<Float4>(h)) {}

WideRecords::WideRecords(std::span<const int> colour, std::span<const std::array<int, 2>> pair_bodies,
                         std::span<const SolverBody> bodies, const WideSoftness& softness,
                         std::pmr::memory_resource* scratch)
    : softness_(softness),
      scratch_(scratch),
      records_(scratch),
      tangent_response_(scratch),
      place_(colour.size(), 0u, scratch),
      row_of_(scratch),
      velocities_(bodies.size() + 1, BodyVelocity{}, scratch),
      loaded_(scratch),
      moves_(bodies.size() + 1, BodyMove{}, scratch) {
    // A pair: a run of rows with the same bodies (detection makes a pair's contacts in a run, and they share a colour).
    struct Pair {
        std::uint32_t first, count;
    };
    std::uint32_t point_count = 0;
    const auto add_record = [&](std::span<const Pair> lanes) {
        RecordX4 record{};
        std::uint32_t most = 0;
        for (const Pair& pair : lanes) most = std::max(most, pair.count);
        record.first_point = point_count;
        record.point_count = most;
        point_count += most;
        for (int lane = 0; lane < 4; ++lane) {
            record.body[0][lane] = record.body[1][lane] = -1;
            if (static_cast<std::size_t>(lane) >= lanes.size()) continue;
            const Pair& pair = lanes[static_cast<std::size_t>(lane)];
            for (std::size_t side = 0; side < 2; ++side) {
                const int b = pair_bodies[pair.first][side];
                record.body[side][lane] = b;
                if (b < 0) continue;
                const MassProperties& mass = bodies[static_cast<std::size_t>(b)].mass;
                record.inverse_mass[side][lane] = static_cast<float>(mass.inverse_mass);
                const Mat3& i = mass.inverse_inertia_world;
                const double e[6] = {i(0, 0), i(0, 1), i(0, 2), i(1, 1), i(1, 2), i(2, 2)};
                for (int k = 0; k < 6; ++k) record.inverse_inertia[side].e[k][lane] = static_cast<float>(e[k]);
            }
            for (std::uint32_t p = 0; p < pair.count; ++p)
                place_[pair.first + p] = (record.first_point + p) * 4 + static_cast<std::uint32_t>(lane);
        }
        records_.push_back(record);
    };
    records_.reserve(colour.size());
    const auto same_bodies = [&](std::size_t a, std::size_t b) {  // (std::array's == calls memcmp)
        return pair_bodies[a][0] == pair_bodies[b][0] && pair_bodies[a][1] == pair_bodies[b][1];
    };
    Pair lanes[4];
    std::size_t filled = 0;
    std::size_t r = 0;
    while (r < colour.size()) {
        std::size_t end = r + 1;
        while (end < colour.size() && colour[end] == colour[r] && same_bodies(end, r)) ++end;
        const Pair pair{static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(end - r)};
        if (colour[r] < 0 || pair.count > 4) {
            // On its own, four points at a time: the overflow's pairs may share bodies, and a lane holds four points.
            for (std::uint32_t k = 0; k < pair.count; k += 4) {
                const Pair part{pair.first + k, std::min<std::uint32_t>(4, pair.count - k)};
                add_record({&part, 1});
            }
        } else {
            lanes[filled++] = pair;
        }
        // A record is full at four pairs, and ends with its colour.
        if (filled == 4 || (filled > 0 && (end == colour.size() || colour[end] != colour[r]))) {
            add_record({lanes, filled});
            filled = 0;
        }
        r = end;
    }
    points_ = {static_cast<PointX4*>(scratch->allocate(point_count * sizeof(PointX4), alignof(PointX4))), point_count};
    bases_ = {static_cast<Mat3x4*>(scratch->allocate(point_count * sizeof(Mat3x4), alignof(Mat3x4))), point_count};
    tangent_response_.resize(point_count);
    row_of_.resize(std::size_t{point_count} * 4, no_row);
    for (std::size_t row = 0; row < place_.size(); ++row) row_of_[place_[row]] = static_cast<std::uint32_t>(row);
    // A lane with no point is zero throughout, so its visits apply nothing; the other lanes are placed.
    for (std::size_t q = 0; q < points_.size(); ++q) {
        const auto lanes = std::span(row_of_).subspan(q * 4, 4);
        if (std::find(lanes.begin(), lanes.end(), no_row) != lanes.end()) {
            new (&points_[q]) PointX4{};
            new (&bases_[q]) Mat3x4{};
        }
    }
}

WideRecords::~WideRecords() {
    static_assert(std::is_trivially_destructible_v<PointX4> && std::is_trivially_destructible_v<Mat3x4>);
    scratch_->deallocate(points_.data(), points_.size() * sizeof(PointX4), alignof(PointX4));
    scratch_->deallocate(bases_.data(), bases_.size() * sizeof(Mat3x4), alignof(Mat3x4));
}

void WideRecords::place(std::size_t r, const ContactRow& row, double prepared_penetration) {
    PointX4& point = points_[place_[r] / 4];
    const int lane = static_cast<int>(place_[r] % 4);
    for (std::size_t side = 0; side < 2; ++side) set_lane(point.anchor[side], lane, row.anchor[side]);
    for (int c = 0; c < 3; ++c) set_lane(bases_[place_[r] / 4].column[c], lane, row.basis.col(c));
    point.normal_mass[lane] = static_cast<float>(row.normal_mass);
    point.friction[lane] = static_cast<float>(row.friction);
    point.prepared_penetration[lane] = static_cast<float>(prepared_penetration);
    point.total.n[lane] = static_cast<float>(row.total_impulse.n);
    point.total.t1[lane] = static_cast<float>(row.total_impulse.t1);
    point.total.t2[lane] = static_cast<float>(row.total_impulse.t2);
}

// A record's points' bases, kept once where each lane's points all have the bits of its first point's (and the same
// lanes hold a point: an empty lane's basis is zero), else one a point quad; moved down over the bases as placed, one
// record after another, so that a sweep reads them in order.
void WideRecords::keep_bases_once() {
    std::uint32_t kept = 0;
    for (RecordX4& record : records_) {
        const std::uint32_t first = record.first_point;
        bool shared = true;
        for (std::uint32_t p = 1; p < record.point_count && shared; ++p)
            for (std::uint32_t lane = 0; lane < 4 && shared; ++lane) {
                const bool placed = row_of_[(first + p) * 4 + lane] != no_row;
                shared = placed == (row_of_[first * 4 + lane] != no_row) &&
                         (!placed || same_lane(bases_[first + p], bases_[first], static_cast<int>(lane)));
            }
        const std::uint32_t count = shared ? 1 : record.point_count;
        if (kept != first)  // kept < first: a copy down, in order (std::copy's destination outside its source)
            std::copy(bases_.begin() + first, bases_.begin() + first + count, bases_.begin() + kept);
        record.basis = kept;
        record.basis_step = shared ? 0 : 1;
        kept += count;
    }
}

std::size_t WideRecords::basis_count() const {
    std::size_t count = 0;
    for (const RecordX4& record : records_) count += record.basis_step == 0 ? 1 : record.point_count;
    return count;
}

void WideRecords::prepare() {
    keep_bases_once();
    const Float4 zero = splat<Float4>(0.0);
    for (const RecordX4& record : records_) {
        // Body 1's share is added in every lane: a static body's (and an empty lane's) masses and anchor are zero.
        for (std::uint32_t p = 0; p < record.point_count; ++p) {
            PointX4& point = points_[record.first_point + p];
            const Mat3x4& basis = bases_[record.basis + p * record.basis_step];
            std::array<Float4, 3>& tangent_response = tangent_response_[record.first_point + p];
            const Mat3x4 body_0 = world_delta_velocity_matrix_of<Mat3x4>(point.anchor[0], record.inverse_inertia[0],
                                                                         record.inverse_mass[0]);
            const Mat3x4 body_1 = world_delta_velocity_matrix_of<Mat3x4>(point.anchor[1], record.inverse_inertia[1],
                                                                         record.inverse_mass[1]);
            const FrictionMatrixOf<Float4> f =
                friction_matrix<Float4>(delta_velocity_matrix_of<Mat3x4, Float4>(basis, body_0, &body_1));
            // A lane without friction keeps no friction rows (fill_contact_row's zeros).
            const Mask4 rows = point.friction != zero;
            for (int k = 0; k < 2; ++k) point.normal_to_tangent[k] = select(rows, f.normal_to_tangent[k], zero);
            for (int k = 0; k < 3; ++k) {
                tangent_response[k] = select(rows, f.tangent_response[k], zero);
                point.tangent_mass[k] = select(rows, f.tangent_mass[k], zero);
            }
            point.tangent_invertible = both(rows, f.tangent_invertible);
            point.penetration = point.prepared_penetration;
            point.most_pushed = zero;
        }
    }
}

void WideRecords::load(std::span<const SolverBody> bodies) {
    for (std::size_t b = 0; b < bodies.size(); ++b)
        for (int k = 0; k < 3; ++k) {
            velocities_[b].velocity[k] = static_cast<float>(bodies[b].velocity[k]);
            velocities_[b].angular_velocity[k] = static_cast<float>(bodies[b].angular_velocity[k]);
        }
    loaded_.assign(velocities_.begin(), velocities_.end());
}

// The change in floats, added in doubles: a body no visit changed keeps its double velocities' bits.
void WideRecords::store(std::span<SolverBody> bodies) {
    for (std::size_t b = 0; b < bodies.size(); ++b)
        for (int k = 0; k < 3; ++k) {
            bodies[b].velocity[k] += double(velocities_[b].velocity[k]) - double(loaded_[b].velocity[k]);
            bodies[b].angular_velocity[k] +=
                double(velocities_[b].angular_velocity[k]) - double(loaded_[b].angular_velocity[k]);
            loaded_[b].velocity[k] = velocities_[b].velocity[k];
            loaded_[b].angular_velocity[k] = velocities_[b].angular_velocity[k];
        }
}

void WideRecords::track(std::size_t body, const Vec3& moved, const Mat3& turned) {
    for (int i = 0; i < 3; ++i) {
        moves_[body].moved[i] = static_cast<float>(moved[i]);
        for (int j = 0; j < 3; ++j) moves_[body].turned[3 * j + i] = static_cast<float>(turned(i, j));
    }
}

void WideRecords::warm_start(WideVisit* kept) {
    if (kept)
        warm_start_records<true>(kept);
    else
        warm_start_records<false>(nullptr);
}

template <bool biased, bool moved>
void WideRecords::sweep(WideVisit* kept) {
    if (kept)
        sweep_records<biased, moved, true>(kept);
    else
        sweep_records<biased, moved, false>(nullptr);
}

template void WideRecords::sweep<true, false>(WideVisit*);
template void WideRecords::sweep<false, false>(WideVisit*);
template void WideRecords::sweep<false, true>(WideVisit*);

template <bool keeping>
void WideRecords::warm_start_records(WideVisit* kept) {
    const std::size_t none = velocities_.size() - 1;
    for (const RecordX4& record : records_) {
        Velocities s = gather(record, velocities_.data(), none);
        for (std::uint32_t p = 0; p < record.point_count; ++p) {
            const std::uint32_t q = record.first_point + p;
            PointX4& point = points_[q];
            const Mat3x4& basis = bases_[record.basis + p * record.basis_step];
            if constexpr (keeping)
                for (int lane = 0; lane < 4; ++lane)
                    if (const std::uint32_t r = row_of_[q * 4 + static_cast<std::uint32_t>(lane)]; r != no_row) {
                        kept[r].velocity = lane_of(contact_velocity(s, point, basis), lane);
                        kept[r].visit = RowVisit{};  // from 0: the total counts what this sub-step has applied
                        kept[r].visit.unclamped = kept[r].visit.after = lane_of(point.total, lane);
                    }
            apply(record, point, basis, s, point.total);
            keep_most_pushed(point, point.total.n);  // the total itself is unchanged: its lines stay clean
        }
        scatter(record, velocities_.data(), s);
    }
}

template <bool biased, bool moved, bool keeping>
void WideRecords::sweep_records(WideVisit* kept) {
    const std::size_t none = velocities_.size() - 1;
    const Float4 one = splat<Float4>(1.0), zero = splat<Float4>(0.0);
    for (const RecordX4& record : records_) {
        Velocities s = gather(record, velocities_.data(), none);
        Vec3x4 moved_by[2];
        Mat3x4 turned_by[2];
        if constexpr (moved)
            for (int side = 0; side < 2; ++side) {
                // Each of the four lanes at once (a lane written alone reads as the register's others unset).
                const BodyMove* body[4];
                for (int lane = 0; lane < 4; ++lane) body[lane] = &body_of(record, side, lane, moves_.data(), none);
                const auto lanes = [&body](int k, auto of) {
                    return Float4{of(*body[0])[k], of(*body[1])[k], of(*body[2])[k], of(*body[3])[k]};
                };
                for (int i = 0; i < 3; ++i) {
                    moved_by[side].v[i] = lanes(i, [](const BodyMove& m) { return m.moved; });
                    for (int j = 0; j < 3; ++j)
                        turned_by[side].column[j].v[i] = lanes(3 * j + i, [](const BodyMove& m) { return m.turned; });
                }
            }
        for (std::uint32_t p = 0; p < record.point_count; ++p) {
            const std::uint32_t q = record.first_point + p;
            PointX4& point = points_[q];
            const Mat3x4& basis = bases_[record.basis + p * record.basis_step];
            if constexpr (moved) {
                // p = p0 - n . [(dx0 + R0 r0 - r0) - (dx1 + R1 r1 - r1)]; a static body's move is zero.
                const Vec3x4 m0 = anchor_move(moved_by[0], turned_by[0], point.anchor[0]);
                const Vec3x4 m1 = anchor_move(moved_by[1], turned_by[1], point.anchor[1]);
                const Vec3x4 separated{m0.x() - m1.x(), m0.y() - m1.y(), m0.z() - m1.z()};
                point.penetration = point.prepared_penetration - dot(separated, basis.column[0]);
            }
            const SoftAimOf<Float4> aim = soft_aim<Float4>(point.penetration, softness_.bias_rate,
                                                           softness_.max_push_velocity, softness_.substep);
            const AxesOf<Float4> velocity = contact_velocity(s, point, basis);
            // soft_step.cpp's target_of, lane by lane.
            NormalTargetOf<Float4> target;
            if constexpr (biased)
                target = {aim.solve_velocity, select(aim.soft, softness_.mass_scale, one),
                          select(aim.soft, softness_.impulse_scale, zero)};
            else
                target = {aim.relax_velocity, one, zero};
            const RowVisitOf<Float4> v = solve_rows<Float4>(point, tangent_response_[q], point.total, velocity, target);
            apply(record, point, basis, s, v.increment());
            keep_total(point, v.after);
            if constexpr (keeping)
                for (int lane = 0; lane < 4; ++lane)
                    if (const std::uint32_t r = row_of_[q * 4 + static_cast<std::uint32_t>(lane)]; r != no_row)
                        kept[r] = {lane_of(velocity, lane),
                                   {lane_of(v.before, lane), lane_of(v.unclamped, lane), lane_of(v.after, lane),
                                    v.pushed_only[lane] != 0, v.sliding[lane] != 0},
                                   target.velocity[lane]};
        }
        scatter(record, velocities_.data(), s);
    }
}

void WideRecords::totals(std::span<Axes> total, std::span<double> most_pushed, std::span<Vec3> world) const {
    for (const RecordX4& record : records_)
        for (std::uint32_t p = 0; p < record.point_count; ++p) {
            const std::uint32_t q = record.first_point + p;
            const PointX4& point = points_[q];
            const Vec3x4 g = world_impulse(bases_[record.basis + p * record.basis_step], point.total);  // as apply's
            for (int lane = 0; lane < 4; ++lane) {
                const std::uint32_t r = row_of_[q * 4 + static_cast<std::uint32_t>(lane)];
                if (r == no_row) continue;
                total[r] = lane_of(point.total, lane);
                most_pushed[r] = std::max(most_pushed[r], double(point.most_pushed[lane]));
                world[r] = Vec3(g.x()[lane], g.y()[lane], g.z()[lane]);
            }
        }
}

}  // namespace impulse
