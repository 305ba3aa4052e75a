#include "methods/method_table.hpp"

#include <algorithm>

namespace impulse {

namespace {

// Every enumerator has its row, in enumerator order, so a new method cannot be half added (the tables have one entry
// per enumerator: a missing row is an empty one, without a function or a name).
template <typename Id, std::size_t N>
constexpr bool rows_in_order(const std::array<MethodRow<Id>, N>& rows) {
    for (std::size_t i = 0; i < N; ++i)
        if (rows[i].id != static_cast<Id>(i) || !rows[i].solve || rows[i].name.empty()) return false;
    return true;
}
static_assert(rows_in_order(velocity_methods));
static_assert(rows_in_order(position_methods));

bool listed(std::span<const std::string_view> keys, std::string_view key) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace

bool reads_setting(const ResolverSettings& settings, std::string_view key) {
    return listed(method_row(settings.velocity_method).reads, key) ||
           listed(method_row(position_method_in_effect(settings)).reads, key);
}

}  // namespace impulse
