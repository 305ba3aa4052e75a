#pragma once
// The gravity and the frame the hand-worked expectations use: the scenes' defaults, 9.81 m/s^2 and 60 Hz.

namespace impulse::test {

inline constexpr double g = 9.81;        // m/s^2
inline constexpr double h = 1.0 / 60.0;  // s: a frame

}  // namespace impulse::test
