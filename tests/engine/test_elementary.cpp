// The engine's own elementary functions (math/elementary.hpp) against the C library's: how far apart they are in
// units in the last place over the ranges a simulation meets, their values at special arguments, and the
// identities they must keep. That they give the same bits in the WebAssembly build is the determinism test's job
// (tests/web/determinism.mjs); here the C library is glibc, within 0.6 ulp of the true values, so a bound here is
// the function's own accuracy (math/elementary.hpp) plus that.

#include "math/elementary.hpp"
#include "math/rotation.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

using namespace impulse;

namespace {

// |a - b| in units of the last place of b.
double ulps(double a, double b) {
    if (a == b) return 0.0;
    const double unit = std::nextafter(std::fabs(b), std::numeric_limits<double>::infinity()) - std::fabs(b);
    return std::fabs(a - b) / unit;
}

// The largest distance over `count` arguments drawn uniformly from [low, high].
double worst(const std::function<double(double)>& ours, const std::function<double(double)>& library, double low,
             double high, int count = 200000) {
    std::mt19937_64 random(20261126);
    std::uniform_real_distribution<double> draw(low, high);
    double most = 0.0;
    for (int i = 0; i < count; ++i) {
        const double x = draw(random);
        most = std::max(most, ulps(ours(x), library(x)));
    }
    return most;
}

// The engine's sine and cosine: sin_cos computes both.
const auto our_sin = [](double x) { return elementary::sin_cos(x).sin; };
const auto our_cos = [](double x) { return elementary::sin_cos(x).cos; };
const auto c_sin = [](double x) { return std::sin(x); };
const auto c_cos = [](double x) { return std::cos(x); };

}  // namespace

TEST_CASE("the engine's sine and cosine stay within 1.5 ulp of the C library's, also far from zero") {
    CHECK(worst(our_sin, c_sin, -10.0, 10.0) <= 1.5);
    CHECK(worst(our_cos, c_cos, -10.0, 10.0) <= 1.5);
    CHECK(worst(our_sin, c_sin, -1e5, 1e5) <= 1.5);
    CHECK(worst(our_cos, c_cos, -1e5, 1e5) <= 1.5);
    // Small angles, where the sine is the angle itself to many digits.
    CHECK(worst(our_sin, c_sin, -1e-3, 1e-3) <= 1.5);
    CHECK(worst(our_cos, c_cos, -1e-3, 1e-3) <= 1.5);
}

TEST_CASE("the engine's tangent and arctangent stay within 3 ulp of the C library's") {
    CHECK(worst(
              elementary::tan, [](double x) { return std::tan(x); }, -1.5, 1.5) <= 3.0);
    CHECK(worst(
              elementary::atan, [](double x) { return std::atan(x); }, -4.0, 4.0) <= 3.0);
    CHECK(worst(
              elementary::atan, [](double x) { return std::atan(x); }, -1e6, 1e6) <= 3.0);
}

TEST_CASE("the engine's exponential, logarithm, power and hypot stay within 2 ulp of the C library's") {
    CHECK(worst(
              elementary::exp, [](double x) { return std::exp(x); }, -700.0, 700.0) <= 2.0);
    CHECK(worst(
              elementary::log, [](double x) { return std::log(x); }, 1e-9, 1e9) <= 2.0);
    CHECK(worst(
              elementary::log, [](double x) { return std::log(x); }, 0.5, 2.0) <= 2.0);
    // A damping factor raised to a time step, as the integrator does.
    const auto damped = [](double dt) { return elementary::pow(0.95, dt); };
    CHECK(worst(
              damped, [](double dt) { return std::pow(0.95, dt); }, 0.0, 0.1) <= 2.0);
    const auto stepped = [](double base) { return elementary::pow(base, 1.0 / 60.0); };
    CHECK(worst(
              stepped, [](double base) { return std::pow(base, 1.0 / 60.0); }, 1e-3, 1.0) <= 2.0);
    const auto length = [](double x) { return elementary::hypot(x, 0.37 * x + 0.1); };
    CHECK(worst(
              length, [](double x) { return std::hypot(x, 0.37 * x + 0.1); }, -10.0, 10.0) <= 2.0);
}

TEST_CASE("the engine's elementary functions give the exact values at their special arguments") {
    constexpr double inf = std::numeric_limits<double>::infinity();
    CHECK(our_sin(0.0) == 0.0);
    CHECK(std::signbit(our_sin(-0.0)));
    CHECK(our_cos(0.0) == 1.0);
    CHECK(elementary::tan(0.0) == 0.0);
    CHECK(elementary::atan(1.0) == std::numbers::pi / 4);
    CHECK(elementary::atan(inf) == std::numbers::pi / 2);
    CHECK(elementary::atan(-inf) == -std::numbers::pi / 2);
    CHECK(elementary::exp(0.0) == 1.0);
    CHECK(elementary::exp(-inf) == 0.0);
    CHECK(elementary::exp(1000.0) == inf);
    CHECK(elementary::log(1.0) == 0.0);
    CHECK(elementary::log(0.0) == -inf);
    CHECK(std::isnan(elementary::log(-1.0)));
    CHECK(elementary::pow(0.5, 2.0) == 0.25);
    CHECK(elementary::pow(0.7, 0.0) == 1.0);
    CHECK(elementary::pow(0.0, 0.5) == 0.0);
    CHECK(std::isnan(elementary::pow(-2.0, 0.5)));
    CHECK(elementary::hypot(3.0, 4.0) == 5.0);
    CHECK(elementary::hypot(0.0, 0.0) == 0.0);
    CHECK(elementary::hypot(-3e300, 4e300) == doctest::Approx(5e300));  // no overflow in the squares
    CHECK(elementary::hypot(3e-300, 4e-300) == doctest::Approx(5e-300));
    CHECK(std::isnan(our_sin(inf)));
    CHECK(std::isnan(our_cos(std::numeric_limits<double>::quiet_NaN())));
}

TEST_CASE("the engine's sine and cosine keep sin^2 + cos^2 = 1 and the quadrants' signs") {
    for (double x = -20.0; x <= 20.0; x += 0.013) {
        const elementary::SinCos sc = elementary::sin_cos(x);
        CHECK(sc.sin * sc.sin + sc.cos * sc.cos == doctest::Approx(1.0).epsilon(1e-15));
        CHECK(std::signbit(sc.sin) == std::signbit(std::sin(x)));
        CHECK(std::signbit(sc.cos) == std::signbit(std::cos(x)));
    }
}

TEST_CASE("an exact orientation update turns by the rotation vector's length, and first order by 2 atan(|theta|/2)") {
    const Vec3 theta(0.3, -0.2, 0.5);
    const Quat start = Quat::Identity();
    const Quat exact = rotated(start, theta, OrientationUpdate::exact);
    CHECK(2.0 * std::acos(exact.w()) == doctest::Approx(theta.norm()).epsilon(1e-14));
    CHECK(turned_angle(theta.norm(), OrientationUpdate::first_order) ==
          doctest::Approx(2.0 * std::atan(0.5 * theta.norm())).epsilon(1e-15));
    CHECK(rotation_magnitude_for_angle(turned_angle(0.4, OrientationUpdate::first_order),
                                       OrientationUpdate::first_order) == doctest::Approx(0.4).epsilon(1e-15));
    // Euler angles: 90 degrees about z takes x to y.
    const Quat z90 = orientation_from_euler_xyz_degrees(Vec3(0.0, 0.0, 90.0));
    const Vec3 turned = z90 * Vec3::UnitX();
    CHECK(turned.x() == doctest::Approx(0.0).epsilon(1e-15));
    CHECK(turned.y() == doctest::Approx(1.0).epsilon(1e-15));
}
