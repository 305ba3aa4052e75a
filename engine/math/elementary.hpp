#pragma once
// The elementary functions the engine uses, of its own: computed with +, -, *, / and sqrt alone, each of which
// IEEE 754 rounds exactly, so every build gives the same bits. The C libraries do not: glibc (the native build)
// and musl (emscripten's, the WebAssembly build) give a different last bit for 3 to 4 % of sines, cosines,
// tangents and arctangents and 14 % of hypot's lengths (measured over a million arguments each), and a trace
// made in the browser must be the trace made on the desktop, to the last bit (docs/design.md, "The browser").
// Jolt and Box3D keep their own for the same reason.
//
// Accuracy, measured against 113-bit results over a million arguments each (tests/engine/test_elementary.cpp
// holds the bounds): sin and cos within 0.8 ulp, exp and pow 1.0, log and hypot 1.2, atan 1.8, tan 2.2 (the C
// library's are within 0.6). sin, cos and tan reduce their argument by pi/2 in three parts, exact while
// |x| < 1.6e6 rad; beyond that they lose accuracy, never determinism.

namespace impulse::elementary {

// sin x and cos x at once, sharing the argument's reduction.
struct SinCos {
    double sin;
    double cos;
};
SinCos sin_cos(double x);
double tan(double x);
double atan(double x);
double exp(double x);
double log(double x);  // natural; NaN below 0, -inf at 0
// base^exponent for base >= 0, as exp(exponent log(base)): accurate while |exponent log(base)| stays small, as it
// does for a damping factor raised to a time step. NaN for a negative base.
double pow(double base, double exponent);
// sqrt(x^2 + y^2), scaled by a power of two where the squares would overflow or underflow.
double hypot(double x, double y);

}  // namespace impulse::elementary
