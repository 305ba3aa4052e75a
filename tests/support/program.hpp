#pragma once
// The impulse-lab program, started as a shell starts it (IMPULSE_LAB_PROGRAM: the cli and course test programs
// define it; tests/CMakeLists.txt).

#include <string>

namespace impulse::test {

inline const std::string program = IMPULSE_LAB_PROGRAM;

}  // namespace impulse::test
