#pragma once
// A shipped case or scene ("cases/ruler", "stack_3") opened as the inspector opens it.

#include "model/session.hpp"
#include "support/shipped.hpp"

#include <string>

namespace impulse::test {

inline model::Session opened_session(const std::string& name, const model::OpenOptions& options = {}) {
    return model::Session::open(shipped_scenes + name + ".json", options);
}

inline Trace opened(const std::string& name, const model::OpenOptions& options = {}) {
    return opened_session(name, options).trace();
}

}  // namespace impulse::test
