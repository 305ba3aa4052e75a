#pragma once
// Comparisons with a tolerance that print both values when they fail.

#include "math/types.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

namespace impulse::test {

inline bool close(double a, double b, double tolerance = 1e-12) {
    return std::abs(a - b) <= tolerance * std::max(1.0, std::max(std::abs(a), std::abs(b)));
}

template <typename A, typename B>
bool close(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, double tolerance = 1e-12) {
    return (a - b).cwiseAbs().maxCoeff() <=
           tolerance * std::max(1.0, std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()));
}

template <typename T>
std::string shown(const T& v) {
    std::ostringstream out;
    out.precision(17);
    if constexpr (std::is_arithmetic_v<T>)
        out << v;
    else
        out << v.transpose();
    return out.str();
}

}  // namespace impulse::test

// CHECK that two numbers or vectors agree to a relative 1e-12 (or the given tolerance), showing both.
#define CHECK_CLOSE(actual, expected, ...)                                      \
    CHECK_MESSAGE(                                                              \
        ::impulse::test::close((actual), (expected)__VA_OPT__(, ) __VA_ARGS__), \
        #actual " = " << ::impulse::test::shown(actual) << ", expected " << ::impulse::test::shown(expected))
