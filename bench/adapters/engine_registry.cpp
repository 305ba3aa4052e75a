// The engines this build has: each adapter's file defines its row, and the build compiles only the adapters
// whose library was found, saying which through IMPULSE_HAVE_<ENGINE> (bench/CMakeLists.txt).

#include "bench/adapters/engine_adapter.hpp"

#include <vector>

namespace impulse::bench {

#ifdef IMPULSE_HAVE_BULLET
extern const EngineRow bullet_engine;
#endif
#ifdef IMPULSE_HAVE_ODE
extern const EngineRow ode_engine;
#endif
#ifdef IMPULSE_HAVE_MUJOCO
extern const EngineRow mujoco_engine;
#endif

namespace {

const std::vector<EngineRow>& engine_rows() {
    static const std::vector<EngineRow> rows{
#ifdef IMPULSE_HAVE_BULLET
        bullet_engine,
#endif
#ifdef IMPULSE_HAVE_ODE
        ode_engine,
#endif
#ifdef IMPULSE_HAVE_MUJOCO
        mujoco_engine,
#endif
    };
    return rows;
}

}  // namespace

std::span<const EngineRow> built_engines() {
    return engine_rows();
}

const EngineRow* find_engine(std::string_view name) {
    for (const EngineRow& row : engine_rows())
        if (row.name == name) return &row;
    return nullptr;
}

}  // namespace impulse::bench
