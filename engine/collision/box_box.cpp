// Two boxes: the separating-axis test over 15 axes (3 face normals of each box and the 9 cross products of
// their edges). If any axis separates them there is no contact; otherwise the axis of least overlap says how
// they touch:
//   a face normal: face contact. The other box's face that faces it most squarely (the incident face) is
//     clipped against the sides of the reference face (Sutherland-Hodgman); every clipped point below the
//     reference face is a contact, up to 8, reduced to the 4 that best keep the supporting area. A box on a
//     corner gives one such point (vertex-face), on an edge two.
//   an edge cross product: edge-edge contact, one point midway between the edges' closest points.
// Face axes are preferred when an edge axis is only slightly shallower, and the faces of the box with the
// lower body index over the other's, so the manifold does not flicker between forms from frame to frame and
// does not depend on the order the two boxes are passed in.

#include "collision/collision.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

namespace impulse {

namespace {

// Cross products shorter than this (sine of the angle between the edges) are parallel edges: no axis.
constexpr double parallel_edges = 1e-6;
// An axis of the other kind must be shallower by this much to be preferred (relative, then absolute).
constexpr double relative_preference = 0.95;
constexpr double absolute_preference = 1e-4;

struct Oriented {
    Vec3 centre;
    Mat3 axes;  // columns: the box's x, y, z in world
    Vec3 half;
};

// (Always inlined, as overlap_along: they run 15 times per pair, and a call costs as much as their arithmetic.)
[[gnu::always_inline]] inline double projected_radius(const Oriented& box, const Vec3& axis) {
    return box.half.x() * std::abs(axis.dot(box.axes.col(0))) + box.half.y() * std::abs(axis.dot(box.axes.col(1))) +
           box.half.z() * std::abs(axis.dot(box.axes.col(2)));
}

struct Axis {
    enum Kind { face_a, face_b, edge } kind;
    int i = 0, j = 0;  // face axis index, or the two edge directions
    Vec3 direction;    // unit, pointing from b to a
    double overlap = std::numeric_limits<double>::infinity();
};

// Overlap along `direction` (any length > 0); negative means the axis separates the boxes. The direction is
// turned to point from b to a; when the centres do not differ along it, the body indices decide, so that
// swapping the two boxes still flips the normal.
[[gnu::always_inline]] inline double overlap_along(const Oriented& a, const Oriented& b, const Vec3& between,
                                                   Vec3 direction, bool a_first, Vec3& oriented) {
    direction.normalize();
    const double along = direction.dot(between);
    if (along < 0.0 || (along == 0.0 && !a_first)) direction = -direction;
    oriented = direction;
    return projected_radius(a, direction) + projected_radius(b, direction) - std::abs(between.dot(direction));
}

struct ClipPoint {
    Vec3 position;
    Feature feature;  // of the incident box: a vertex, or the edge (or face) the point lies on
    Feature onward;   // what the polygon's side from this point to the next lies on: an edge, or the face
};

// At most N items in place (no allocation: a box pair is tested hundreds of times a frame). The incident face
// has 4 corners and each of the 4 side planes clips off at most one corner of a convex polygon, adding at most
// one point: 8 at most.
template <typename T, std::size_t N>
class Few {
public:
    void push_back(const T& item) {
        assert(count_ < N);
        items_[count_++] = item;
    }
    T& back() { return items_[count_ - 1]; }
    const T& operator[](std::size_t k) const { return items_[k]; }
    std::size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }
    const T* begin() const { return items_.data(); }
    const T* end() const { return items_.data() + count_; }

private:
    std::array<T, N> items_;  // only the first count_ are set
    std::size_t count_ = 0;
};

constexpr std::size_t most_points = 8;
using Polygon = Few<ClipPoint, most_points>;

// Keeps the part of the polygon with plane_normal . x <= plane_offset (Sutherland-Hodgman). A point made
// where a side crosses the plane lies on that side's feature; the new side it starts along the plane runs
// across the incident face.
Polygon clip(const Polygon& polygon, const Vec3& plane_normal, double plane_offset, const Feature& incident_face) {
    Polygon kept;
    const std::size_t count = polygon.size();
    if (count == 0) return kept;
    // Each corner's signed distance from the plane, once (a side reads its two ends).
    std::array<double, most_points> distance;
    for (std::size_t k = 0; k < count; ++k) distance[k] = plane_normal.dot(polygon[k].position) - plane_offset;
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t next = k + 1 == count ? 0 : k + 1;
        const ClipPoint& p = polygon[k];
        const ClipPoint& q = polygon[next];
        const double dp = distance[k];
        const double dq = distance[next];
        if (dp <= 0.0) kept.push_back(p);
        const auto crossing = [&] { return Vec3(p.position + (dp / (dp - dq)) * (q.position - p.position)); };
        if (dp <= 0.0 && dq > 0.0) {
            // Leaving: the side to the next kept point runs along the plane, across the incident face. A point
            // exactly on the plane is its own crossing (no duplicate).
            if (dp < 0.0)
                kept.push_back({crossing(), p.onward, incident_face});
            else
                kept.back().onward = incident_face;
        } else if (dp > 0.0 && dq < 0.0) {
            // Entering: the rest of this side continues to q. (q on the plane is kept when its turn comes.)
            kept.push_back({crossing(), p.onward, p.onward});
        }
    }
    return kept;
}

// Twice the area of the convex hull of four points in the plane with normal n (any order).
double hull_area(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s, const Vec3& n) {
    const auto quad = [&n](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
        return std::abs((c - a).cross(d - b).dot(n));  // a quadrilateral's area from its diagonals
    };
    const auto triangle = [&n](const Vec3& a, const Vec3& b, const Vec3& c) {
        return std::abs((b - a).cross(c - a).dot(n));
    };
    // In convex position one of the three orders is the hull; otherwise one point lies in the others' triangle.
    return std::max({quad(p, q, r, s), quad(p, q, s, r), quad(p, r, q, s), triangle(p, q, r), triangle(p, q, s),
                     triangle(p, r, s), triangle(q, r, s)});
}

// The points to keep, ascending: all of them when there are at most four; of more, the deepest, the one farthest
// from it, the one making the largest triangle with those two, and the one adding the most area to that triangle:
// the quadrilateral that best keeps the support area.
Few<std::size_t, 4> reduce_to_four(const Few<Vec3, most_points>& points, const Few<double, most_points>& depth,
                                   const Vec3& normal) {
    Few<std::size_t, 4> keep;
    if (points.size() <= 4) {
        for (std::size_t k = 0; k < points.size(); ++k) keep.push_back(k);
        return keep;
    }
    const std::size_t first = static_cast<std::size_t>(std::max_element(depth.begin(), depth.end()) - depth.begin());
    const auto best = [&points](auto score) {
        std::size_t chosen = 0;
        double most = -1.0;
        for (std::size_t k = 0; k < points.size(); ++k)
            if (const double v = score(points[k]); v > most) most = v, chosen = k;
        return chosen;
    };
    const Vec3& p1 = points[first];
    const std::size_t second = best([&](const Vec3& q) { return (q - p1).squaredNorm(); });
    const Vec3& p2 = points[second];
    const std::size_t third = best([&](const Vec3& q) { return std::abs((p2 - p1).cross(q - p1).dot(normal)); });
    const Vec3& p3 = points[third];
    const std::size_t fourth = best([&](const Vec3& q) { return hull_area(p1, p2, p3, q, normal); });
    std::array<std::size_t, 4> sorted{first, second, third, fourth};
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 0; k < sorted.size(); ++k)
        if (k == 0 || sorted[k] != sorted[k - 1]) keep.push_back(sorted[k]);
    return keep;
}

void face_contact(const Oriented& a, const Oriented& b, int ia, int ib, const Axis& axis, double margin,
                  std::vector<Contact>& out) {
    // The reference box owns the face normal; its face towards the other box has outward normal -n when it is
    // box a (n points from b to a) and +n when it is box b.
    const bool reference_is_a = axis.kind == Axis::face_a;
    const Oriented& reference = reference_is_a ? a : b;
    const Oriented& incident = reference_is_a ? b : a;
    const Vec3 ref_normal = reference_is_a ? Vec3(-axis.direction) : axis.direction;
    const int ref_axis = axis.i;
    const bool ref_negative = reference.axes.col(ref_axis).dot(ref_normal) < 0.0;
    const Feature ref_face{FeatureKind::face, box_face(ref_axis, ref_negative)};

    // The incident face: the face of the other box whose outward normal is most opposed to ref_normal.
    int inc_axis = 0;
    double most_opposed = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double d = incident.axes.col(k).dot(ref_normal);
        if (std::abs(d) > std::abs(most_opposed)) most_opposed = d, inc_axis = k;
    }
    const bool inc_negative = most_opposed > 0.0;  // the face pointing against ref_normal
    const int u = (inc_axis + 1) % 3, v = (inc_axis + 2) % 3;
    // Its four corners in order round the face, with their vertex numbers, and the edges between them.
    const Feature incident_face{FeatureKind::face, box_face(inc_axis, inc_negative)};
    Polygon polygon;
    const std::array<std::array<int, 2>, 4> corners{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    for (std::size_t k = 0; k < 4; ++k) {
        std::array<int, 3> negative{};
        negative[static_cast<std::size_t>(inc_axis)] = inc_negative ? 1 : 0;
        negative[static_cast<std::size_t>(u)] = corners[k][0];
        negative[static_cast<std::size_t>(v)] = corners[k][1];
        const int vertex = negative[0] | (negative[1] << 1) | (negative[2] << 2);
        // The side from this corner to the next runs along u (k = 0, 2) or v (k = 1, 3).
        polygon.push_back({incident.centre + incident.axes * box_vertex(incident.half, vertex),
                           {FeatureKind::vertex, vertex},
                           {FeatureKind::edge, box_edge(k % 2 == 0 ? u : v, negative)}});
    }

    // Clip against the four side planes of the reference face.
    const Vec3 face_centre = reference.centre + ref_normal * reference.half[ref_axis];
    for (int side = 1; side <= 2 && !polygon.empty(); ++side) {
        const int k = (ref_axis + side) % 3;
        const Vec3 direction = reference.axes.col(k);
        const double centre = direction.dot(reference.centre);
        polygon = clip(polygon, direction, centre + reference.half[k], incident_face);
        if (!polygon.empty()) polygon = clip(polygon, -direction, -centre + reference.half[k], incident_face);
    }

    // Keep the points below the reference face; each is on the incident box, `depth` inside the reference box.
    // With a margin, also the points up to `margin` above it (depth < 0): speculative points, which let the solver
    // stop a landing face on all its corners, not on the one that happened to touch first (Box3D keeps a
    // manifold's points within its speculative distance, 2 cm; docs/methods.md, "Speculative points").
    Few<Vec3, most_points> points;
    Few<double, most_points> depth;
    Few<Feature, most_points> features;
    const double face_level = ref_normal.dot(face_centre);
    for (const ClipPoint& p : polygon) {
        const double d = face_level - ref_normal.dot(p.position);
        if (d < -margin) continue;
        points.push_back(p.position);
        depth.push_back(d);
        features.push_back(p.feature);
    }
    // Each contact made whole where it goes (not made empty and then assigned: a face contact gives most of the
    // points of a stack or a pyramid).
    for (const std::size_t k : reduce_to_four(points, depth, ref_normal)) {
        out.push_back({.bodies = {ia, ib},
                       .point = points[k] + ref_normal * (0.5 * depth[k]),  // midway between incident point and face
                       .normal = axis.direction,
                       .penetration = depth[k],
                       .origin = {.test = CollisionTest::box_box,
                                  .features = reference_is_a ? std::array<Feature, 2>{ref_face, features[k]}
                                                             : std::array<Feature, 2>{features[k], ref_face}}});
    }
}

void edge_contact(const Oriented& a, const Oriented& b, int ia, int ib, const Axis& axis, std::vector<Contact>& out) {
    const Vec3& n = axis.direction;  // from b to a
    // Each box's edge along the axis pair that lies furthest towards the other box.
    const auto supporting_edge = [](const Oriented& box, int along, const Vec3& towards, Vec3& start,
                                    Feature& feature) {
        std::array<int, 3> negative{};
        Vec3 local = Vec3::Zero();
        for (int k = 0; k < 3; ++k) {
            if (k == along) continue;
            const bool neg = box.axes.col(k).dot(towards) < 0.0;
            negative[static_cast<std::size_t>(k)] = neg ? 1 : 0;
            local[k] = neg ? -box.half[k] : box.half[k];
        }
        start = box.centre + box.axes * local;  // the edge's midpoint
        feature = {FeatureKind::edge, box_edge(along, negative)};
    };
    Vec3 pa, pb;
    Feature fa, fb;
    supporting_edge(a, axis.i, -n, pa, fa);
    supporting_edge(b, axis.j, n, pb, fb);
    // Closest points of the two edge lines, pa + s da and pb + t db (the standard two-line solution).
    const Vec3 da = a.axes.col(axis.i), db = b.axes.col(axis.j);
    const Vec3 r = pa - pb;
    const double dadb = da.dot(db), dar = da.dot(r), dbr = db.dot(r);
    const double denominator = 1.0 - dadb * dadb;  // > 0: parallel edges give no edge axis
    // Clamp to the edges' lengths: clamp s, take the t closest to that point, clamp it, and take the s closest
    // to that; for two segments this reaches their closest points.
    double s = std::clamp((dadb * dbr - dar) / denominator, -a.half[axis.i], a.half[axis.i]);
    const double t = std::clamp(dbr + s * dadb, -b.half[axis.j], b.half[axis.j]);
    s = std::clamp(t * dadb - dar, -a.half[axis.i], a.half[axis.i]);
    Contact c;
    c.bodies = {ia, ib};
    c.normal = n;
    c.penetration = axis.overlap;
    c.point = 0.5 * ((pa + s * da) + (pb + t * db));
    c.origin = {CollisionTest::box_box, {fa, fb}};
    out.push_back(c);
}

bool clearly_shallower(double candidate, double incumbent) {
    return candidate < relative_preference * incumbent - absolute_preference;
}

// The separating-axis test as it is defined: every axis's exact overlap, in the order face a_0, face b_0, a_1, b_1,
// a_2, b_2, then the edges a_i x b_j; the least of each kind, the first on a tie. Nothing if an axis separates.
std::optional<Axis> least_overlap_every_axis(const Oriented& A, const Oriented& B, const Vec3& between, int a, int b) {
    constexpr double none = std::numeric_limits<double>::infinity();
    Axis best_a{Axis::face_a, 0, 0, Vec3::Zero(), none}, best_b{Axis::face_b, 0, 0, Vec3::Zero(), none},
        best_edge{Axis::edge, 0, 0, Vec3::Zero(), none};
    Vec3 direction;
    for (int k = 0; k < 3; ++k) {
        double o = overlap_along(A, B, between, A.axes.col(k), a < b, direction);
        if (o < 0.0) return std::nullopt;
        if (o < best_a.overlap) best_a = {Axis::face_a, k, 0, direction, o};
        o = overlap_along(A, B, between, B.axes.col(k), a < b, direction);
        if (o < 0.0) return std::nullopt;
        if (o < best_b.overlap) best_b = {Axis::face_b, k, 0, direction, o};
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            // Lower-numbered body's edge x the other's, whichever order the boxes came in, so the tie-break in
            // overlap_along flips it exactly once when they are swapped.
            const Vec3 cross = (a < b ? 1.0 : -1.0) * A.axes.col(i).cross(B.axes.col(j));
            if (cross.norm() < parallel_edges) continue;
            const double o = overlap_along(A, B, between, cross, a < b, direction);
            if (o < 0.0) return std::nullopt;
            if (o < best_edge.overlap) best_edge = {Axis::edge, i, j, direction, o};
        }
    // The faces of the box with the lower body index first; the other box's faces only if clearly shallower,
    // then an edge axis only if clearly shallower than those.
    const Axis& preferred = a < b ? best_a : best_b;
    const Axis& other = a < b ? best_b : best_a;
    Axis best = clearly_shallower(other.overlap, preferred.overlap) ? other : preferred;
    if (clearly_shallower(best_edge.overlap, best.overlap)) best = best_edge;
    return best;
}

// The axes in the exact test's order: face a_0, face b_0, a_1, b_1, a_2, b_2, then the edges a_i x b_j.
constexpr int axis_count = 15;

// The first pass of least_overlap_screened: every axis's overlap estimated from the dot products of the boxes'
// axes, R_ij = a_i . b_j, and of the centres' offset (Gottschalk, Lin and Manocha 1996, OBBTree): along a face
// axis a_i the overlap is h_a,i + sum_j h_b,j |R_ij| - |t . a_i|, along an edge axis a_i x b_j each radius takes
// two terms of |R| (the box's other two axes).
struct OverlapEstimates {
    std::array<double, axis_count> estimate;
    std::array<bool, axis_count> exists;
    std::array<Vec3, 9> cross;  // edge axes, lower-numbered body's edge first
    double screen;              // how far an estimate may be from the exact overlap, with a wide margin
};

OverlapEstimates estimated_overlaps(const Oriented& A, const Oriented& B, const Vec3& between, bool a_first) {
    const Vec3& ha = A.half;
    const Vec3& hb = B.half;
    double abs_r[3][3], ta[3], tb[3];
    for (int i = 0; i < 3; ++i) {
        ta[i] = between.dot(A.axes.col(i));
        tb[i] = between.dot(B.axes.col(i));
        for (int j = 0; j < 3; ++j) abs_r[i][j] = std::abs(A.axes.col(i).dot(B.axes.col(j)));
    }
    OverlapEstimates e;
    e.screen = 1e-9 * (ha.sum() + hb.sum() + between.norm());
    const double order = a_first ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k) {
        e.estimate[2 * k] = ha[k] + (hb[0] * abs_r[k][0] + hb[1] * abs_r[k][1] + hb[2] * abs_r[k][2]) - std::abs(ta[k]);
        e.estimate[2 * k + 1] =
            hb[k] + (ha[0] * abs_r[0][k] + ha[1] * abs_r[1][k] + ha[2] * abs_r[2][k]) - std::abs(tb[k]);
        e.exists[2 * k] = e.exists[2 * k + 1] = true;
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int edge = 3 * i + j, at = 6 + edge;
            // Lower-numbered body's edge x the other's, whichever order the boxes came in, so the tie-break in
            // overlap_along flips it exactly once when they are swapped.
            e.cross[edge] = order * A.axes.col(i).cross(B.axes.col(j));
            const double length = e.cross[edge].norm();
            e.exists[at] = length >= parallel_edges;
            if (!e.exists[at]) continue;
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const double radius_a = ha[i1] * abs_r[i2][j] + ha[i2] * abs_r[i1][j];
            const double radius_b = hb[j1] * abs_r[i][j2] + hb[j2] * abs_r[i][j1];
            e.estimate[at] = (radius_a + radius_b - std::abs(between.dot(e.cross[edge]))) / length;
        }
    return e;
}

// The same choice from about half the arithmetic (box_and_box's; the test compares the two on random pairs).
std::optional<Axis> least_overlap_screened(const Oriented& A, const Oriented& B, const Vec3& between, int a, int b) {
    // The separating-axis test in two passes. The first estimates every axis's overlap (estimated_overlaps). The
    // second computes the exact overlap (overlap_along) only where an estimate could decide otherwise than the
    // exact value would: an axis estimated within `screen` of zero (does it separate?) and the axes within
    // `screen` of their kind's least overlap (which is least?). Estimate and exact value differ by rounding, far
    // less than `screen`, so the decisions are those of the exact test on every axis, and the chosen axes'
    // directions and overlaps are the exact ones: the same contacts to the bit, for about half the arithmetic.
    const OverlapEstimates estimates = estimated_overlaps(A, B, between, a < b);
    const std::array<double, axis_count>& estimate = estimates.estimate;
    const std::array<bool, axis_count>& exists = estimates.exists;
    const std::array<Vec3, 9>& cross = estimates.cross;
    const double screen = estimates.screen;
    const auto exact = [&](int at, Vec3& direction) {
        const Vec3 axis = at < 6 ? (at % 2 == 0 ? A.axes.col(at / 2) : B.axes.col(at / 2)) : cross[at - 6];
        return overlap_along(A, B, between, axis, a < b, direction);
    };

    // Does any axis separate the boxes?
    Vec3 direction;
    for (int at = 0; at < axis_count; ++at) {
        if (!exists[at] || estimate[at] > screen) continue;
        if (estimate[at] < -screen || exact(at, direction) < 0.0) return std::nullopt;
    }
    // The least overlap of each kind, the first in the exact test's order on a tie. A kind that has to be clearly
    // shallower than the incumbent to win (see below) is looked at exactly only if its estimate leaves it a chance.
    constexpr double none = std::numeric_limits<double>::infinity();
    const auto least = [&](Axis::Kind kind, int first, int last, int step, double incumbent) {
        Axis best{kind, 0, 0, Vec3::Zero(), none};
        double smallest = none;
        for (int at = first; at < last; at += step)
            if (exists[at]) smallest = std::min(smallest, estimate[at]);
        if (!clearly_shallower(smallest - 2.0 * screen, incumbent)) return best;  // cannot win: no need to know
        for (int at = first; at < last; at += step) {
            if (!exists[at] || estimate[at] > smallest + 2.0 * screen) continue;
            const double o = exact(at, direction);
            if (o < best.overlap)
                best = {kind, at < 6 ? at / 2 : (at - 6) / 3, at < 6 ? 0 : (at - 6) % 3, direction, o};
        }
        return best;
    };
    // The same preferences as the exhaustive test.
    const bool a_preferred = a < b;
    const Axis preferred = least(a_preferred ? Axis::face_a : Axis::face_b, a_preferred ? 0 : 1, 6, 2, none);
    const Axis other = least(a_preferred ? Axis::face_b : Axis::face_a, a_preferred ? 1 : 0, 6, 2, preferred.overlap);
    Axis best = clearly_shallower(other.overlap, preferred.overlap) ? other : preferred;
    const Axis edge = least(Axis::edge, 6, axis_count, 1, best.overlap);
    if (clearly_shallower(edge.overlap, best.overlap)) best = edge;
    return best;
}

template <std::optional<Axis> (*choose)(const Oriented&, const Oriented&, const Vec3&, int, int)>
void boxes(const Box& ba, const Placement& pa, int a, const Box& bb, const Placement& pb, int b, double margin,
           std::vector<Contact>& out) {
    const Oriented A{pa.position, pa.rotation, ba.half_size};
    const Oriented B{pb.position, pb.rotation, bb.half_size};
    const std::optional<Axis> best = choose(A, B, A.centre - B.centre, a, b);
    if (!best) return;
    if (best->kind == Axis::edge)
        edge_contact(A, B, a, b, *best, out);
    else
        face_contact(A, B, a, b, *best, margin, out);
}

}  // namespace

void box_and_box(const Box& ba, const Placement& pa, int a, const Box& bb, const Placement& pb, int b,
                 std::vector<Contact>& out, double margin) {
    boxes<least_overlap_screened>(ba, pa, a, bb, pb, b, margin, out);
}

void box_and_box_every_axis(const Box& ba, const Placement& pa, int a, const Box& bb, const Placement& pb, int b,
                            std::vector<Contact>& out, double margin) {
    boxes<least_overlap_every_axis>(ba, pa, a, bb, pb, b, margin, out);
}

}  // namespace impulse
