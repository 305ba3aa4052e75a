#pragma once
// How close a number must be to the reference's to match it: diff's grading, and the worksheet's rounding of
// inputs for work by hand (a rounded input must still let every cell match).

namespace impulse::course {

struct Tolerance {
    double rtol = 1e-9;   // the reference engine's arithmetic agrees with ours to about 1e-12 relative
    double atol = 1e-12;  // so that an expected 0 is matched by rounding noise, not by any small number
};

}  // namespace impulse::course
