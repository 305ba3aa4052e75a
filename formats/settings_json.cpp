#include "formats/settings_json.hpp"

#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/schemas.hpp"
#include "formats/settings_names.hpp"

namespace impulse::formats {

namespace {

template <typename Enum, std::size_t N>
Enum read_enum(const NameTable<Enum, N>& table, const json& value) {
    // The schema's enum already limited the word to the table's names.
    return *value_of(table, value.get<std::string>());
}

// Applies every field present in `object` (already schema-checked) to the scene's settings.
void apply_fields(Scene& scene, const json& object, std::string_view path) {
    ResolverSettings& s = scene.settings;
    const auto has = [&object](const char* key) { return object.contains(key); };
    if (has("phase_order")) s.phase_order = read_enum(phase_order_names, object["phase_order"]);
    if (has("position_method")) s.position_method = read_enum(position_method_names, object["position_method"]);
    if (has("velocity_method")) s.velocity_method = read_enum(velocity_method_names, object["velocity_method"]);
    if (has("worst_first_search"))
        s.worst_first_search = read_enum(worst_first_search_names, object["worst_first_search"]);
    if (has("sliding_friction")) s.sliding_friction = read_enum(sliding_friction_names, object["sliding_friction"]);
    if (has("sweeps")) s.sweeps = object["sweeps"].get<int>();
    if (has("warm_start")) s.warm_start = object["warm_start"].get<bool>();
    if (has("baumgarte")) s.baumgarte = object["baumgarte"].get<bool>();
    if (has("position_bias")) {
        const json& bias = object["position_bias"];
        if (bias.contains("factor")) s.position_bias.factor = bias["factor"].get<double>();
        if (bias.contains("slop")) s.position_bias.slop = bias["slop"].get<double>();
    }
    if (has("soft_step")) {
        const json& soft = object["soft_step"];
        if (soft.contains("substeps")) s.soft_step.substeps = soft["substeps"].get<int>();
        if (soft.contains("contact_hertz")) s.soft_step.contact_hertz = soft["contact_hertz"].get<double>();
        if (soft.contains("damping_ratio")) s.soft_step.damping_ratio = soft["damping_ratio"].get<double>();
        if (soft.contains("max_push_velocity")) s.soft_step.max_push_velocity = soft["max_push_velocity"].get<double>();
        if (soft.contains("order")) s.soft_step.order = read_enum(solve_order_names, soft["order"]);
    }
    if (has("recycling")) {
        const json& recycling = object["recycling"];
        if (recycling.contains("distance")) s.recycling.distance = recycling["distance"].get<double>();
        if (recycling.contains("angle")) s.recycling.angle = recycling["angle"].get<double>();
    }
    if (has("speculative_margin")) s.speculative_margin = object["speculative_margin"].get<double>();
    if (has("avbd")) {
        const json& avbd = object["avbd"];
        const auto number = [&avbd](const char* key, double& value) {
            if (avbd.contains(key)) value = avbd[key].get<double>();
        };
        if (avbd.contains("iterations")) s.avbd.iterations = avbd["iterations"].get<int>();
        number("alpha", s.avbd.alpha);
        number("beta", s.avbd.beta);
        number("gamma", s.avbd.gamma);
        number("stiffness_min", s.avbd.stiffness_min);
        number("stiffness_max", s.avbd.stiffness_max);
        number("slop", s.avbd.slop);
        if (avbd.contains("post_stabilize")) s.avbd.post_stabilize = avbd["post_stabilize"].get<bool>();
        if (!(s.avbd.stiffness_min <= s.avbd.stiffness_max))
            throw InputError(json_path_child(json_path_child(path, "avbd"), "stiffness_min"),
                             "must be at most avbd.stiffness_max (" + number_text(s.avbd.stiffness_max) + "), got " +
                                 number_text(s.avbd.stiffness_min));
    }
    if (has("angular_limit")) {
        const json& limit = object["angular_limit"];
        if (limit.contains("policy")) {
            s.angular_limit.policy = read_enum(angular_limit_policy_names, limit["policy"]);
            // A policy given without its factor gets that policy's own default, never another policy's.
            s.angular_limit.factor = default_angular_limit_factor(s.angular_limit.policy);
        }
        if (limit.contains("factor")) s.angular_limit.factor = limit["factor"].get<double>();
        if (s.angular_limit.policy == AngularLimitPolicy::angle &&
            !(s.angular_limit.factor > 0.0 && s.angular_limit.factor < 180.0))
            throw InputError(json_path_child(json_path_child(path, "angular_limit"), "factor"),
                             "the angle policy's factor is a turn in degrees and must be > 0 and < 180, got " +
                                 number_text(s.angular_limit.factor));
    }
    if (has("relaxation")) {
        const json& relaxation = object["relaxation"];
        if (relaxation.contains("fraction")) s.relaxation.fraction = relaxation["fraction"].get<double>();
        if (relaxation.contains("passes")) s.relaxation.passes = relaxation["passes"].get<int>();
    }
    if (has("position_epsilon")) s.position_epsilon = object["position_epsilon"].get<double>();
    if (has("velocity_epsilon")) s.velocity_epsilon = object["velocity_epsilon"].get<double>();
    if (has("iterations_per_contact")) s.iterations_per_contact = object["iterations_per_contact"].get<int>();
    const auto fixed_limit = [&object](const char* key) -> std::optional<int> {
        const json& v = object[key];
        return v.is_null() ? std::nullopt : std::optional<int>(v.get<int>());
    };
    if (has("position_iterations")) s.position_iterations = fixed_limit("position_iterations");
    if (has("velocity_iterations")) s.velocity_iterations = fixed_limit("velocity_iterations");
    if (has("restitution_cutoff")) s.restitution_cutoff = object["restitution_cutoff"].get<double>();
    if (has("velocity_from_acceleration"))
        s.velocity_from_acceleration = object["velocity_from_acceleration"].get<bool>();
    if (has("tangential_acceleration_velocity"))
        s.tangential_acceleration_velocity = object["tangential_acceleration_velocity"].get<bool>();
    if (has("orientation_update"))
        s.orientation_update = read_enum(orientation_update_names, object["orientation_update"]);
    if (has("duration")) s.duration = object["duration"].get<double>();
    if (has("frames")) scene.world.frames = object["frames"].get<int>();
    if (has("linear_damping")) scene.world.linear_damping = object["linear_damping"].get<double>();
    if (has("angular_damping")) scene.world.angular_damping = object["angular_damping"].get<double>();
}

}  // namespace

void read_settings(Scene& scene, const json* settings, std::string_view path,
                   const std::optional<std::string>& preset_override) {
    std::string preset_name = "book";
    if (settings && settings->contains("preset")) preset_name = (*settings)["preset"].get<std::string>();
    if (preset_override) preset_name = *preset_override;
    const std::optional<ResolverSettings> s = preset(preset_name);
    if (!s)
        throw InputError("--preset", "unknown preset \"" + preset_name + "\"; expected one of " + preset_list_text());
    scene.settings = *s;
    if (settings) apply_fields(scene, *settings, path);
}

json settings_json(const ResolverSettings& s, const WorldSettings& world) {
    const auto fixed_limit = [](const std::optional<int>& v) { return v ? json(*v) : json(nullptr); };
    json out = {
        {"preset", s.preset},
        {"phase_order", name_of(phase_order_names, s.phase_order)},
        {"position_method", name_of(position_method_names, s.position_method)},
        {"velocity_method", name_of(velocity_method_names, s.velocity_method)},
        {"worst_first_search", name_of(worst_first_search_names, s.worst_first_search)},
        {"sweeps", s.sweeps},
        {"warm_start", s.warm_start},
        {"position_bias", {{"factor", s.position_bias.factor}, {"slop", s.position_bias.slop}}},
        {"soft_step",
         {{"substeps", s.soft_step.substeps},
          {"contact_hertz", s.soft_step.contact_hertz},
          {"damping_ratio", s.soft_step.damping_ratio},
          {"max_push_velocity", s.soft_step.max_push_velocity}}},
        {"angular_limit",
         {{"policy", name_of(angular_limit_policy_names, s.angular_limit.policy)}, {"factor", s.angular_limit.factor}}},
        {"relaxation", {{"fraction", s.relaxation.fraction}, {"passes", s.relaxation.passes}}},
        {"position_epsilon", s.position_epsilon},
        {"velocity_epsilon", s.velocity_epsilon},
        {"iterations_per_contact", s.iterations_per_contact},
        {"position_iterations", fixed_limit(s.position_iterations)},
        {"velocity_iterations", fixed_limit(s.velocity_iterations)},
        {"restitution_cutoff", s.restitution_cutoff},
        {"velocity_from_acceleration", s.velocity_from_acceleration},
        {"tangential_acceleration_velocity", s.tangential_acceleration_velocity},
        {"orientation_update", name_of(orientation_update_names, s.orientation_update)},
        {"duration", s.duration},
        {"frames", world.frames},
        {"linear_damping", world.linear_damping},
        {"angular_damping", world.angular_damping},
    };
    // Settings added after trace format 1 was fixed are written only when they differ from what older versions
    // did without them (no Baumgarte term in step 5 unless the old `baumgarte` position method was chosen, the
    // reference sliding friction, detection's order, no recycling, no margin), so the traces older versions can read
    // stay byte-identical and readable; and whenever the run's preset sets them otherwise, since a reader starts from
    // the preset: pgs with its Baumgarte term switched off, or soft_step_recycled without recycling, reads back so.
    const ResolverSettings unset{};
    const std::optional<ResolverSettings> named = preset(s.preset);
    const auto needed = [&](const auto& field) {
        return field(s) != field(unset) || (named && field(*named) != field(unset));
    };
    if (needed([](const ResolverSettings& r) { return r.baumgarte; })) out["baumgarte"] = s.baumgarte;
    if (needed([](const ResolverSettings& r) { return r.sliding_friction; }))
        out["sliding_friction"] = name_of(sliding_friction_names, s.sliding_friction);
    if (needed([](const ResolverSettings& r) { return r.soft_step.order; }))
        out["soft_step"]["order"] = name_of(solve_order_names, s.soft_step.order);
    if (needed([](const ResolverSettings& r) { return r.recycling; }))
        out["recycling"] = {{"distance", s.recycling.distance}, {"angle", s.recycling.angle}};
    if (needed([](const ResolverSettings& r) { return r.speculative_margin; }))
        out["speculative_margin"] = s.speculative_margin;
    if (s.velocity_method == VelocityMethod::avbd || s.avbd != AvbdSettings{})
        out["avbd"] = {{"iterations", s.avbd.iterations},
                       {"alpha", s.avbd.alpha},
                       {"beta", s.avbd.beta},
                       {"gamma", s.avbd.gamma},
                       {"stiffness_min", s.avbd.stiffness_min},
                       {"stiffness_max", s.avbd.stiffness_max},
                       {"slop", s.avbd.slop},
                       {"post_stabilize", s.avbd.post_stabilize}};
    return out;
}

void refuse_renamed_settings(const json& settings, std::string_view path) {
    if (!settings.is_object() || !settings.contains("position_method")) return;
    const json& method = settings["position_method"];
    if (method.is_string() && method.get_ref<const std::string&>() == "baumgarte")
        throw InputError(json_path_child(path, "position_method"),
                         "\"baumgarte\" is no longer a position method: Baumgarte's bias is now a term of step 5 "
                         "(did you mean \"position_method\": \"none\" with \"baumgarte\": true?)");
}

void apply_setting(Scene& scene, std::string_view assignment, std::string_view flag) {
    const std::size_t equals = assignment.find('=');
    if (equals == std::string_view::npos || equals == 0)
        throw InputError(std::string(flag), "expected name=value, got \"" + std::string(assignment) + "\"");
    const std::string name(assignment.substr(0, equals));
    const std::string text(assignment.substr(equals + 1));
    json value;
    try {
        value = parse_json_text(text);
    } catch (const InputError&) {
        value = text;  // a bare word such as lever_arm is a string
    }
    // angular_limit.policy=angle becomes {"angular_limit": {"policy": "angle"}}.
    json object = json::object();
    json* at = &object;
    std::size_t start = 0;
    for (std::size_t dot = name.find('.'); dot != std::string::npos; dot = name.find('.', start)) {
        at = &(*at)[name.substr(start, dot - start)];
        start = dot + 1;
    }
    (*at)[name.substr(start)] = value;
    if (object.contains("preset")) {
        const std::optional<ResolverSettings> base =
            preset(object["preset"].is_string() ? object["preset"].get<std::string>() : "");
        if (!base)
            throw InputError(std::string(flag),
                             "preset: must be one of " + preset_list_text() + ", got " + value.dump());
        scene.settings = *base;
        return;
    }
    // Errors read "--set angular_limit.factor: must be >= 0, got -1".
    try {
        refuse_renamed_settings(object, "");
        validate_settings_object(object, "");
        apply_fields(scene, object, "");
    } catch (const InputError& e) {
        throw InputError(std::string(flag) + " " + e.where(), e.problem());
    }
}

}  // namespace impulse::formats
