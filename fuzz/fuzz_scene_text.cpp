// libFuzzer target: fuzz_loaders.hpp, load_scene_text.

#include "fuzz_target.hpp"

IMPULSE_FUZZ_TARGET(load_scene_text)
