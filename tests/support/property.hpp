#pragma once
// Property tests with rapidcheck inside doctest. Each property runs at least 1000 cases from a fixed seed, so
// CI is deterministic; RC_PARAMS="seed=N" (or "reproduce=...") overrides it to explore or to replay a
// failure. A failure is reported with rapidcheck's shrunk counter-example.

#include <doctest/doctest.h>
#include <rapidcheck.h>

#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>

namespace impulse::test {

inline constexpr int property_cases = 1000;

template <typename Testable>
void check_property(const std::string& description, Testable&& testable, int cases = property_cases) {
    rc::detail::TestParams params = rc::detail::configuration().testParams;
    params.maxSuccess = std::max(params.maxSuccess, cases);
    const char* user = std::getenv("RC_PARAMS");
    if (!user || std::string(user).find("seed=") == std::string::npos)
        params.seed = std::hash<std::string>{}(description);  // fixed per property
    rc::detail::TestMetadata metadata;
    metadata.id = description;
    metadata.description = description;
    const auto result = rc::detail::checkTestable(std::forward<Testable>(testable), metadata, params);
    if (!result.template is<rc::detail::SuccessResult>()) {
        std::ostringstream message;
        rc::detail::printResultMessage(result, message);
        FAIL(description << "\n" << message.str());
    } else {
        CHECK(result.template get<rc::detail::SuccessResult>().numSuccess >= cases);
    }
}

}  // namespace impulse::test
