// Contact generation against cases derived by hand: which contacts, where, how deep, which features.

#include "collision/collision.hpp"
#include "support/approx.hpp"
#include "support/bodies.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace impulse;
using namespace impulse::test;

namespace {

const HalfSpace ground{Vec3::UnitY(), 0.0};
using impulse::test::cube;

Placement at(const Vec3& position, const Quat& orientation = Quat::Identity()) {
    return {position, orientation.toRotationMatrix()};
}

Quat about(const Vec3& axis, double degrees) {
    return Quat(Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axis.normalized()));
}

std::vector<int> feature_indices(const std::vector<Contact>& contacts, int body) {
    std::vector<int> indices;
    for (const Contact& c : contacts) indices.push_back(c.origin.features[static_cast<std::size_t>(body)].index);
    std::sort(indices.begin(), indices.end());
    return indices;
}

// The area the contact points of a manifold on a horizontal face enclose (ordered round their centre).
double manifold_area(const std::vector<Contact>& contacts) {
    std::vector<Vec3> p;
    for (const Contact& c : contacts) p.push_back(c.point);
    Vec3 centre = Vec3::Zero();
    for (const Vec3& q : p) centre += q / static_cast<double>(p.size());
    std::sort(p.begin(), p.end(), [&](const Vec3& a, const Vec3& b) {
        return std::atan2(a.z() - centre.z(), a.x() - centre.x()) < std::atan2(b.z() - centre.z(), b.x() - centre.x());
    });
    double area = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k)
        area += 0.5 * (p[k] - centre).cross(p[(k + 1) % p.size()] - centre).norm();
    return area;
}

// True if some contact is at `point` (to 1e-12).
bool has_point(const std::vector<Contact>& contacts, const Vec3& point) {
    return std::any_of(contacts.begin(), contacts.end(),
                       [&](const Contact& c) { return (c.point - point).norm() < 1e-12; });
}

}  // namespace

TEST_CASE("a box lying flat 1 cm into the ground touches it at its four bottom corners") {
    // Half-sizes (0.5, 0.25, 0.5), centre at y = 0.24: the bottom face is at y = -0.01. Bottom vertices have
    // y negative (bit 1 set): 2, 3, 6, 7. Each contact sits ON its vertex, 0.01 deep, normal +y.
    std::vector<Contact> out;
    box_and_half_space(Box{Vec3(0.5, 0.25, 0.5)}, at({0, 0.24, 0}), 0, ground, out);
    REQUIRE(out.size() == 4);
    CHECK(feature_indices(out, 0) == std::vector<int>{2, 3, 6, 7});
    for (const Contact& c : out) {
        CHECK(c.bodies == std::array<int, 2>{0, world_body});
        CHECK_CLOSE(c.normal, Vec3::UnitY());
        CHECK_CLOSE(c.penetration, 0.01);
        CHECK(c.origin.test == CollisionTest::box_half_space);
        CHECK(c.origin.features[1].kind == FeatureKind::plane);
    }
    for (double x : {-0.5, 0.5})
        for (double z : {-0.5, 0.5}) CHECK(has_point(out, Vec3(x, -0.01, z)));
}

TEST_CASE("a cube resting on an edge touches the ground at the edge's two vertices") {
    // Turned 45 degrees about z, the vertices with x and y both negative (bits 0 and 1: vertices 3 and 7)
    // are lowest, at y = centre - 0.5 sqrt(2) and x = 0.
    std::vector<Contact> out;
    const double centre = 0.5 * std::sqrt(2.0) - 0.01;
    box_and_half_space(cube, at({0, centre, 0}, about(Vec3::UnitZ(), 45)), 0, ground, out);
    REQUIRE(out.size() == 2);
    CHECK(feature_indices(out, 0) == std::vector<int>{3, 7});
    CHECK(has_point(out, Vec3(0, -0.01, 0.5)));
    CHECK(has_point(out, Vec3(0, -0.01, -0.5)));
    for (const Contact& c : out) CHECK_CLOSE(c.penetration, 0.01);
}

TEST_CASE("a cube balanced on a corner touches the ground at that one vertex") {
    // Turn the body diagonal towards vertex 7 (-,-,-) straight down: that vertex is 0.5 sqrt(3) below the
    // centre; its three neighbours are only 0.5 sqrt(3) - 1/sqrt(3) = 0.289 below it.
    std::vector<Contact> out;
    const Quat corner_down = Quat::FromTwoVectors(Vec3(-1, -1, -1).normalized(), -Vec3::UnitY());
    box_and_half_space(cube, at({0, 0.5 * std::sqrt(3.0) - 0.01, 0}, corner_down), 0, ground, out);
    REQUIRE(out.size() == 1);
    CHECK(out[0].origin.features[0] == Feature{FeatureKind::vertex, 7});
    CHECK_CLOSE(out[0].penetration, 0.01);
    CHECK_CLOSE(out[0].point, Vec3(0, -0.01, 0));
}

TEST_CASE("a sphere meets the ground at its lowest point") {
    std::vector<Contact> out;
    sphere_and_half_space(Sphere{0.5}, at({1, 0.45, 2}), 0, ground, out);
    REQUIRE(out.size() == 1);
    CHECK_CLOSE(out[0].penetration, 0.05);
    CHECK_CLOSE(out[0].point, Vec3(1, -0.05, 2));
    sphere_and_half_space(Sphere{0.5}, at({1, 0.51, 2}), 0, ground, out);
    CHECK(out.size() == 1);  // 1 cm above: no contact
}

TEST_CASE("two spheres touch midway between their surfaces, the normal from body 1 to body 0") {
    // Body 0: r = 0.3 at (0.7, 0, 0); body 1: r = 0.5 at the origin. Distance 0.7: 0.1 deep. Body 1's surface
    // is at x = 0.5, body 0's at 0.4: the point is at 0.45.
    std::vector<Contact> out;
    sphere_and_sphere(Sphere{0.3}, at({0.7, 0, 0}), 0, Sphere{0.5}, at(Vec3::Zero()), 1, out);
    REQUIRE(out.size() == 1);
    CHECK_CLOSE(out[0].normal, Vec3::UnitX());
    CHECK_CLOSE(out[0].penetration, 0.1);
    CHECK_CLOSE(out[0].point, Vec3(0.45, 0, 0));
}

TEST_CASE("a sphere against a box face, edge and corner") {
    // Cube of half-size 0.5 at the origin, sphere r = 0.3. The normal points from the sphere (body 1) to
    // the box (body 0); the point is midway between the box's surface and the sphere's deepest point.
    const auto hit = [](const Vec3& centre) {
        std::vector<Contact> out;
        box_and_sphere(cube, at(Vec3::Zero()), 0, Sphere{0.3}, at(centre), 1, out);
        return out;
    };
    // Face +y (face 2): centre 0.25 above it, 0.05 deep; point 0.025 below the face.
    std::vector<Contact> face = hit({0, 0.75, 0});
    REQUIRE(face.size() == 1);
    CHECK(face[0].origin.features[0] == Feature{FeatureKind::face, 2});
    CHECK_CLOSE(face[0].normal, Vec3(0, -1, 0));
    CHECK_CLOSE(face[0].penetration, 0.05);
    CHECK_CLOSE(face[0].point, Vec3(0, 0.475, 0));
    // Edge along z at x = +0.5, y = +0.5 (edge 8): distance sqrt(0.08).
    std::vector<Contact> edge = hit({0.7, 0.7, 0});
    REQUIRE(edge.size() == 1);
    const double edge_depth = 0.3 - std::sqrt(0.08);
    CHECK(edge[0].origin.features[0] == Feature{FeatureKind::edge, 8});
    CHECK_CLOSE(edge[0].normal, Vec3(-1, -1, 0).normalized());
    CHECK_CLOSE(edge[0].penetration, edge_depth);
    CHECK_CLOSE(edge[0].point, Vec3(Vec3(0.5, 0.5, 0) + edge[0].normal * (0.5 * edge_depth)));
    // Corner (+,+,+) (vertex 0): distance sqrt(3 * 0.0225).
    std::vector<Contact> corner = hit({0.65, 0.65, 0.65});
    REQUIRE(corner.size() == 1);
    const double corner_depth = 0.3 - std::sqrt(3 * 0.0225);
    CHECK(corner[0].origin.features[0] == Feature{FeatureKind::vertex, 0});
    CHECK_CLOSE(corner[0].normal, Vec3(-1, -1, -1).normalized());
    CHECK_CLOSE(corner[0].penetration, corner_depth);
    CHECK_CLOSE(corner[0].point, Vec3(Vec3(0.5, 0.5, 0.5) + corner[0].normal * (0.5 * corner_depth)));
    // Centre inside, 0.1 below face +y: out through that face, 0.3 + 0.1 deep; the sphere's deepest point is
    // 0.3 below its centre at y = 0.1, the face at 0.5, so the point is midway at y = 0.3.
    std::vector<Contact> inside = hit({0, 0.4, 0});
    REQUIRE(inside.size() == 1);
    CHECK(inside[0].origin.features[0] == Feature{FeatureKind::face, 2});
    CHECK_CLOSE(inside[0].normal, Vec3(0, -1, 0));
    CHECK_CLOSE(inside[0].penetration, 0.4);
    CHECK_CLOSE(inside[0].point, Vec3(0, 0.3, 0));
    // Out of reach: nothing.
    CHECK(hit({0, 0.81, 0}).empty());
}

TEST_CASE("two boxes face to face give a four-point manifold at the corners of their overlap") {
    // Box 0 (half 0.5) at (0.2, 0.99, 0) on box 1 (half 0.5) at the origin: overlap x in [-0.3, 0.5],
    // z in [-0.5, 0.5], 0.01 deep. Box 0's bottom face (face 3) is the reference; box 1's top face is clipped to
    // it: two of its vertices (0: (+,+,+), 4: (+,+,-)) and two points where its x edges (0 and 2) cross box 0's
    // side x = -0.3. Points midway between the surfaces: y = 0.495.
    std::vector<Contact> out;
    box_and_box(cube, at({0.2, 0.99, 0}), 0, cube, at(Vec3::Zero()), 1, out);
    REQUIRE(out.size() == 4);
    for (const Contact& c : out) {
        CHECK(c.bodies == std::array<int, 2>{0, 1});
        CHECK_CLOSE(c.normal, Vec3::UnitY());
        CHECK_CLOSE(c.penetration, 0.01);
        CHECK(c.origin.test == CollisionTest::box_box);
        CHECK(c.origin.features[0] == Feature{FeatureKind::face, 3});
    }
    for (double x : {-0.3, 0.5})
        for (double z : {-0.5, 0.5}) CHECK(has_point(out, Vec3(x, 0.495, z)));
    std::vector<Feature> incident;
    for (const Contact& c : out) incident.push_back(c.origin.features[1]);
    const auto holds = [&](Feature f) { return std::find(incident.begin(), incident.end(), f) != incident.end(); };
    CHECK(holds({FeatureKind::vertex, 0}));
    CHECK(holds({FeatureKind::vertex, 4}));
    CHECK(holds({FeatureKind::edge, 0}));
    CHECK(holds({FeatureKind::edge, 2}));
}

TEST_CASE("a box turned 45 degrees on another clips to an octagon, reduced to the four points that keep most area") {
    // The clipped incident face is a regular octagon of 8 points, all 0.01 deep. Keeping 4 of them must keep
    // most of its area: the octagon's area is 2 (sqrt(2) - 1) = 0.828 of the square; the best quadrilateral of
    // its vertices covers at least half of the octagon.
    std::vector<Contact> out;
    box_and_box(cube, at({0, 0.99, 0}, about(Vec3::UnitY(), 45)), 0, cube, at(Vec3::Zero()), 1, out);
    REQUIRE(out.size() == 4);
    const double area = manifold_area(out);
    const double octagon = 2.0 * (std::sqrt(2.0) - 1.0);
    CHECK(area > 0.5 * octagon);
}

TEST_CASE("a five-point clip keeps the four points that hold nearly all of its area") {
    // Regression: the 3rd and 4th points were the largest triangles on either side of the line through the
    // deepest and farthest points; when those two were neighbours every point lay on one side and only 3 were
    // kept (area 0.48 of a 0.70 polygon). The best 4 of these 5 points hold 0.70.
    const Quat turn = about(Vec3::UnitX(), 0.2) * about(Vec3::UnitZ(), -0.3) * about(Vec3::UnitY(), 27.9);
    std::vector<Contact> out;
    box_and_box(cube, at({0.8227, 0.989, 0.3374}, turn), 0, Box{Vec3(1, 0.5, 1)}, at(Vec3::Zero()), 1, out);
    REQUIRE(out.size() == 4);
    const double area = manifold_area(out);
    CHECK(area > 0.95 * 0.701);
}

TEST_CASE("crossed edges give one contact midway between the edges' closest points") {
    // Box 0 turned 45 degrees about x at height 1.4, box 1 turned 45 degrees about z at the origin: box 0's
    // lowest edge runs along x at y = 1.4 - 0.5 sqrt(2), box 1's highest along z at y = 0.5 sqrt(2). They cross
    // above the origin, 2 (0.5 sqrt(2)) - 1.4 = 0.01421 deep; the point is midway, at y = 0.7.
    std::vector<Contact> out;
    box_and_box(cube, at({0, 1.4, 0}, about(Vec3::UnitX(), 45)), 0, cube, at(Vec3::Zero(), about(Vec3::UnitZ(), 45)), 1,
                out);
    REQUIRE(out.size() == 1);
    // Box 0's lowest edge runs along its x with y negative, z positive (edge 1); box 1's highest along its z
    // with x and y positive (edge 8).
    CHECK(out[0].origin.features[0] == Feature{FeatureKind::edge, 1});
    CHECK(out[0].origin.features[1] == Feature{FeatureKind::edge, 8});
    CHECK_CLOSE(out[0].normal, Vec3::UnitY());
    CHECK_CLOSE(out[0].penetration, std::sqrt(2.0) - 1.4);
    CHECK_CLOSE(out[0].point, Vec3(0, 0.7, 0));
}

TEST_CASE("a box balanced on its corner on another box's face gives one vertex-face contact") {
    std::vector<Contact> out;
    const Quat corner_down = Quat::FromTwoVectors(Vec3(-1, -1, -1).normalized(), -Vec3::UnitY());
    box_and_box(cube, at({0, 0.5 + 0.5 * std::sqrt(3.0) - 0.01, 0}, corner_down), 0, cube, at(Vec3::Zero()), 1, out);
    REQUIRE(out.size() == 1);
    CHECK(out[0].origin.features[0] == Feature{FeatureKind::vertex, 7});
    CHECK(out[0].origin.features[1] == Feature{FeatureKind::face, 2});
    CHECK_CLOSE(out[0].penetration, 0.01);
    CHECK_CLOSE(out[0].normal, Vec3::UnitY());
}

TEST_CASE("boxes apart along any of the 15 axes give no contact") {
    std::vector<Contact> out;
    box_and_box(cube, at({0, 1.01, 0}), 0, cube, at(Vec3::Zero()), 1, out);  // a face axis separates
    box_and_box(cube, at({0, 1.43, 0}, about(Vec3::UnitX(), 45)), 0, cube, at(Vec3::Zero(), about(Vec3::UnitZ(), 45)),
                1,
                out);  // only the edge-edge axis separates
    CHECK(out.empty());
}
