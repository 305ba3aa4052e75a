#include "math/elementary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impulse::elementary {

// Only operations IEEE 754 defines exactly are used here: +, -, *, /, std::sqrt, and the exact ones std::floor,
// std::fabs, std::frexp and std::ldexp (a power of two changes only the exponent). The constants below are the
// true values rounded to double (hex literals, computed to 80 decimal digits); a constant split in _hi and _lo
// holds the value to about 107 bits.

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

// pi/2 in three parts of 33 bits each (the last rounded), so k * part is exact for |k| < 2^20 (Cody and Waite).
constexpr double half_pi_1 = 0x1.921fb54400000p+0;
constexpr double half_pi_2 = 0x1.0b4611a600000p-34;
constexpr double half_pi_3 = 0x1.3198a2e037073p-69;
constexpr double two_over_pi = 0x1.45f306dc9c883p-1;
constexpr double half_pi_hi = 0x1.921fb54442d18p+0;
constexpr double half_pi_lo = 0x1.1a62633145c07p-54;

// x = k pi/2 + r: r as a sum r + tail with |r| <= about pi/4, and k's quadrant, k mod 4.
struct Reduced {
    double r;
    double tail;
    int quadrant;
};

Reduced reduce(double x) {
    if (std::fabs(x) <= 0x1.921fb54442d18p-1) return {x, 0.0, 0};  // |x| <= pi/4: nothing to take away
    const double k = std::floor(x * two_over_pi + 0.5);
    // x - k p1 is exact (Sterbenz), and so is k p2; the subtraction's own error is kept in the tail.
    const double t = x - k * half_pi_1;
    const double w = k * half_pi_2;
    const double r0 = t - w;
    const double tail0 = (t - r0) - w;
    const double w3 = k * half_pi_3;
    const double r = r0 - w3;
    const double tail = ((r0 - r) - w3) + tail0;
    return {r, tail, static_cast<int>(k - 4.0 * std::floor(k * 0.25))};  // exact, for any size of k
}

// sin(r + tail) for |r| <= pi/4: the Taylor series to r^19 (the next term is below 2^-60 of the result), plus
// tail cos(r) ~ tail (1 - r^2/2).
double sin_kernel(double r, double tail) {
    const double s = r * r;
    const double p =
        -1.0 / 6 +
        s * (1.0 / 120 +
             s * (-1.0 / 5040 +
                  s * (1.0 / 362880 +
                       s * (-1.0 / 39916800 + s * (1.0 / 6227020800 + s * (-1.0 / 1307674368000 +
                                                                           s * (1.0 / 355687428096000 +
                                                                                s * (-1.0 / 121645100408832000))))))));
    return r + (r * s * p + tail * (1.0 - 0.5 * s));
}

// cos(r + tail) for |r| <= pi/4: 1 - r^2/2 + r^4 q(r^2) to r^18, with the rounding of 1 - r^2/2 recovered
// (|r^2/2| <= 1, so (1 - w) - h is exact), minus tail sin(r) ~ tail r.
double cos_kernel(double r, double tail) {
    const double s = r * r;
    const double q =
        1.0 / 24 +
        s * (-1.0 / 720 +
             s * (1.0 / 40320 +
                  s * (-1.0 / 3628800 +
                       s * (1.0 / 479001600 +
                            s * (-1.0 / 87178291200 + s * (1.0 / 20922789888000 + s * (-1.0 / 6402373705728000)))))));
    const double h = 0.5 * s;
    const double w = 1.0 - h;
    return w + (((1.0 - w) - h) + (s * s * q - r * tail));
}

// atan(t) for |t| <= 1/8: t - t^3/3 + t^5/5 - ... to t^21 (the next term is below 2^-63 of the result).
double atan_kernel(double t) {
    const double s = t * t;
    double sum = 1.0 / 21;
    for (int k = 19; k >= 3; k -= 2) sum = (((k / 2) % 2 == 0) ? 1.0 : -1.0) / k + s * sum;
    return t + t * s * sum;
}

// atan(c) at the points the argument is reduced to, each split in two.
struct Point {
    double c, hi, lo;
};
constexpr Point atan_points[] = {
    {0.25, 0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57},
    {0.5, 0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56},
    {0.75, 0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56},
    {1.0, 0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55},
};

// ln 2 in two parts, the first of 32 bits (so k ln2_hi is exact for the exponents a double has).
constexpr double ln2_hi = 0x1.62e42ff000000p-1;
constexpr double ln2_lo = -0x1.718432a1b0e26p-35;
constexpr double inverse_ln2 = 0x1.71547652b82fep+0;

}  // namespace

SinCos sin_cos(double x) {
    if (!std::isfinite(x)) return {nan, nan};
    if (x == 0.0) return {x, 1.0};  // sin(-0) = -0
    const Reduced a = reduce(x);
    const double s = sin_kernel(a.r, a.tail), c = cos_kernel(a.r, a.tail);
    switch (a.quadrant) {  // the quadrant: sin(r + k pi/2)
        case 0:
            return {s, c};
        case 1:
            return {c, -s};
        case 2:
            return {-s, -c};
        default:
            return {-c, s};
    }
}

double tan(double x) {
    if (!std::isfinite(x)) return nan;
    if (x == 0.0) return x;
    const Reduced a = reduce(x);
    const double s = sin_kernel(a.r, a.tail), c = cos_kernel(a.r, a.tail);
    return a.quadrant % 2 == 0 ? s / c : -c / s;  // tan(r + pi/2) = -cot r
}

double atan(double x) {
    if (std::isnan(x)) return nan;
    const double sign = x < 0.0 ? -1.0 : 1.0;
    double a = std::fabs(x);
    // Beyond 1: atan a = pi/2 - atan(1/a).
    const bool inverted = a > 1.0;
    if (inverted) a = 1.0 / a;  // 0 for infinity: atan = pi/2
    // atan a = atan c + atan((a - c) / (1 + a c)) with c the nearest of 0, 1/4, 1/2, 3/4, 1: |t| <= 1/8.
    double result;
    if (a <= 0.125) {
        result = atan_kernel(a);
    } else {
        const Point& p = atan_points[std::min(3, static_cast<int>(std::floor(a * 4.0 + 0.5)) - 1)];
        const double t = (a - p.c) / (1.0 + a * p.c);
        result = p.hi + (atan_kernel(t) + p.lo);
    }
    if (inverted) result = half_pi_hi - (result - half_pi_lo);
    return sign * result;
}

double exp(double x) {
    if (std::isnan(x)) return nan;
    if (x > 709.782712893384) return infinity;
    if (x < -745.1332191019412) return 0.0;
    // x = k ln 2 + r with |r| <= ln2 / 2; e^x = 2^k e^r, e^r = 1 + r + r^2/2! + ... to r^13 (the next term is
    // below 2^-60).
    const double k = std::floor(x * inverse_ln2 + 0.5);
    const double r = (x - k * ln2_hi) - k * ln2_lo;
    double sum = 1.0 / 6227020800;  // 1/13!
    double factorial = 6227020800;
    for (int n = 12; n >= 2; --n) {
        factorial /= (n + 1);
        sum = 1.0 / factorial + r * sum;
    }
    const double expm1 = r + r * r * sum;
    return std::ldexp(1.0 + expm1, static_cast<int>(k));
}

double log(double x) {
    if (std::isnan(x) || x < 0.0) return nan;
    if (x == 0.0) return -infinity;
    if (std::isinf(x)) return infinity;
    // x = m 2^e with m in [sqrt(1/2), sqrt(2)); log(m) = log(1 + f) = 2 atanh(s), s = f / (2 + f), |s| < 0.172.
    int e = 0;
    double m = std::frexp(x, &e);
    if (m < 0x1.6a09e667f3bcdp-1) m *= 2.0, --e;
    const double f = m - 1.0;
    const double s = f / (2.0 + f);
    const double z = s * s;
    // 2 atanh s = 2s + R with R = 2 s^3/3 + 2 s^5/5 + ... to s^21; and 2s = f - s f, so log(1 + f) = f - s (f - R/s).
    double series = 2.0 / 21;
    for (int k = 19; k >= 3; k -= 2) series = 2.0 / k + z * series;
    const double log_m = f - s * (f - z * series);
    return e * ln2_hi + (log_m + e * ln2_lo);
}

double pow(double base, double exponent) {
    if (std::isnan(base) || std::isnan(exponent) || base < 0.0) return nan;
    if (exponent == 0.0 || base == 1.0) return 1.0;
    if (base == 0.0) return exponent > 0.0 ? 0.0 : infinity;
    return exp(exponent * log(base));
}

double hypot(double x, double y) {
    x = std::fabs(x), y = std::fabs(y);
    if (std::isinf(x) || std::isinf(y)) return infinity;
    const double big = x > y ? x : y;
    // Squares of numbers beyond 2^500 overflow and below 2^-500 lose digits: scale those by a power of two first.
    int scale = 0;
    if (big > 0x1p+500)
        scale = 600;
    else if (big < 0x1p-500 && big > 0.0)
        scale = -600;
    if (scale != 0) x = std::ldexp(x, -scale), y = std::ldexp(y, -scale);
    return std::ldexp(std::sqrt(x * x + y * y), scale);
}

}  // namespace impulse::elementary
