// The hand worker of the worksheets' blank-cell test (hand_worker.hpp): one formula per kind of step, each the
// engine's derivation function applied to the values the sheet gives.

#include "hand_worker.hpp"

#include "course/json_path.hpp"
#include "course/worksheet.hpp"
#include "derivation/avbd/contact_force.hpp"
#include "derivation/contact_velocity.hpp"
#include "derivation/delta_velocity_per_unit_impulse.hpp"
#include "derivation/desired_delta_velocity.hpp"
#include "derivation/impulse.hpp"
#include "derivation/position_change.hpp"
#include "derivation/relative_position.hpp"
#include "derivation/velocity_change.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/settings_names.hpp"
#include "support/impulse.hpp"

#include <doctest/doctest.h>

#include <map>
#include <regex>

using namespace impulse;
using namespace impulse::course;

namespace {

// A value the sheet does not give (yet): the step waits for it.
struct NotYet {
    std::string path;
};

Vec3 vec(const formats::json& j) {
    return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

Mat3 mat(const formats::json& j) {
    Mat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m(r, c) = j[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].get<double>();
    return m;
}

formats::json json_of(const Vec3& v) {
    return formats::json::array({v.x(), v.y(), v.z()});
}

formats::json json_of(const Mat3& m) {
    formats::json rows = formats::json::array();
    for (int r = 0; r < 3; ++r) rows.push_back(formats::json::array({m(r, 0), m(r, 1), m(r, 2)}));
    return rows;
}

template <typename Enum, std::size_t N>
std::string name(const formats::NameTable<Enum, N>& table, Enum value) {
    return std::string(formats::name_of(table, value));
}

template <typename Enum, std::size_t N>
Enum named(const formats::NameTable<Enum, N>& table, const formats::json& text) {
    for (const auto& [value, word] : table)
        if (word == text.get<std::string>()) return value;
    FAIL("no such name: " << text.dump());
    return table[0].first;
}

std::string at(const std::string& path, const std::string& key) {
    return formats::json_path_child(path, key);
}

std::string at(const std::string& path, std::size_t index) {
    return formats::json_path_index(path, index);
}

class HandWorker {
public:
    HandWorker(const formats::json& sheet, const formats::json& reference) : sheet_(sheet), reference_(reference) {
        for (const formats::json& step : sheet["steps"])
            for (const formats::json& input : step["inputs"]) known_[input["path"].get<std::string>()] = input["value"];
    }

    // Fills every cell it can; returns the steps it could not do and what each waited for.
    std::vector<std::string> work() {
        std::vector<bool> done(sheet_["steps"].size(), false);
        std::map<std::size_t, std::string> waiting;
        for (bool progress = true; progress;) {
            progress = false;
            for (std::size_t s = 0; s < done.size(); ++s) {
                if (done[s]) continue;
                const formats::json& step = sheet_["steps"][s];
                try {
                    out_.clear();
                    work_step(step);
                } catch (const NotYet& missing) {
                    waiting[s] = missing.path;
                    continue;
                }
                for (const formats::json& cell : step["cells"]) {
                    const std::string path = cell["path"].get<std::string>();
                    const auto found = out_.find(path);
                    CAPTURE(step["place"].get<std::string>());
                    REQUIRE_MESSAGE(found != out_.end(), "the hand worker has no formula for " << path);
                    known_[path] = found->second;
                }
                done[s] = progress = true;
                waiting.erase(s);
            }
        }
        std::vector<std::string> undone;
        for (const auto& [s, path] : waiting)
            undone.push_back(sheet_["steps"][s]["place"].get<std::string>() + " waits for " + path);
        return undone;
    }

    // The sheet with every cell filled as worked out.
    formats::json filled() const {
        formats::json sheet = sheet_;
        for (formats::json& step : sheet["steps"])
            for (formats::json& cell : step["cells"]) {
                const auto found = known_.find(cell["path"].get<std::string>());
                if (found != known_.end()) cell["value"] = found->second;
            }
        return sheet;
    }

private:
    // A value the sheet gives or that was worked out (in an earlier step, or earlier in this one: an update
    // starts from the one before it).
    const formats::json& k(const std::string& path) const {
        if (const auto here = out_.find(path); here != out_.end()) return here->second;
        const auto found = known_.find(path);
        if (found == known_.end()) throw NotYet{path};
        return found->second;
    }
    bool has(const std::string& path) const { return known_.count(path) == 1 || out_.count(path) == 1; }
    double number(const std::string& path) const { return k(path).get<double>(); }
    // The sheet's settings block names the sliding model (the trace names it only when it is not the
    // reference engine's).
    SlidingFriction sliding_friction() const {
        const formats::json& settings = sheet_["settings"];
        return settings.contains("sliding_friction")
                   ? named(formats::sliding_friction_names, settings["sliding_friction"])
                   : SlidingFriction::reference;
    }

    void put(const std::string& path, formats::json value) { out_[path] = std::move(value); }

    // The contact `contact` as the frame's contacts list holds it (shipped runs record every contact, so the
    // contact numbered c is contacts[c]).
    std::string contact_path(const formats::json& contact) const {
        return at(at(frame_, "contacts"), contact.get<std::size_t>());
    }

    // The u-th update of an iteration's table: its path, the other contact (as numbered), the slot the moved body
    // has in it, which of the visited contact's `bodies` moved, and the other contact's path.
    struct Update {
        std::string path;
        formats::json other;
        std::size_t slot;
        std::size_t moved;
        std::string contact;
    };
    Update update_at(const std::string& updates, std::size_t u, const formats::json& bodies) const {
        const std::string update = at(updates, u);
        const formats::json& other = k(at(update, "contact"));
        return {update, other, k(at(update, "slot")).get<std::size_t>(),
                bodies[0] == k(at(update, "body")) ? std::size_t{0} : std::size_t{1}, contact_path(other)};
    }

    MassProperties mass(const formats::json& body) const {
        const auto b = body.get<std::size_t>();
        return {number(at(at("scene.bodies", b), "inverse_mass")),
                mat(k(at(at(at(frame_, "bodies_before"), b), "inverse_inertia_world")))};
    }

    PerBody<MassProperties> masses(const formats::json& bodies) const {
        PerBody<MassProperties> m;
        for (std::size_t i = 0; i < 2; ++i)
            if (!bodies[i].is_null()) m[i] = mass(bodies[i]);
        return m;
    }

    // What accelerated the body last frame: the scene's, or gravity for a simulated frame's movable body.
    Vec3 acceleration(const formats::json& body) const {
        const auto b = body.get<std::size_t>();
        const std::string own = at(at("scene.bodies", b), "last_frame_acceleration");
        if (has(own)) return vec(k(own));
        if (!has("scene.gravity")) throw NotYet{own};
        return mass(body).inverse_mass > 0.0 ? vec(k("scene.gravity")) : Vec3::Zero();
    }

    PerBody<BodyMotion> accelerations(const formats::json& bodies) const {
        PerBody<BodyMotion> motion;
        for (std::size_t i = 0; i < 2; ++i)
            if (!bodies[i].is_null()) motion[i] = BodyMotion{Vec3::Zero(), Vec3::Zero(), acceleration(bodies[i])};
        return motion;
    }

    PerBody<Vec3> relative_positions(const std::string& contact, const formats::json& bodies) const {
        PerBody<Vec3> q;
        for (std::size_t i = 0; i < 2; ++i)
            if (!bodies[i].is_null()) q[i] = vec(k(at(at(contact, "relative_position"), i)));
        return q;
    }

    Basis basis_of(const formats::json& matrix) const {
        Basis b;
        b.contact_to_world = mat(matrix);
        b.seed = TangentSeed::world_x;
        return b;
    }

    // Where contact `contact`'s `key` ("penetration", "contact_velocity", "desired_delta_velocity") stood before
    // update `update` of iteration `iteration` (npos: before the iteration): the rule of the update tables.
    std::string current(const std::string& phase, std::size_t iteration, std::size_t update,
                        const formats::json& contact, const std::string& key, const std::string& after) const {
        const std::string iterations = at(phase, "iterations");
        const formats::json& recorded = *value_at(reference_, parse_json_path(iterations, ""));
        const auto last_update = [&](std::size_t i, std::size_t before) -> std::optional<std::string> {
            const std::size_t count = recorded[i]["updates"].size();
            for (std::size_t u = std::min(before, count); u-- > 0;) {
                const std::string update_path = at(at(at(iterations, i), "updates"), u);
                if (recorded[i]["updates"][u]["contact"] == contact) return at(update_path, after);
            }
            return std::nullopt;
        };
        if (update != std::string::npos) {
            if (auto path = last_update(iteration, update)) return *path;
            if (k(at(at(iterations, iteration), "contact")) == contact) return at(at(iterations, iteration), key);
        }
        for (std::size_t i = iteration; i-- > 0;)
            if (auto path = last_update(i, SIZE_MAX)) return *path;
        return at(contact_path(contact), key);
    }

    void work_step(const formats::json& step) {
        static const std::regex item_pattern(
            R"(^(frames\[(\d+)\])\.(contacts\[\d+\]|phases\[(\d+)\]\.iterations\[(\d+)\]))");
        const std::string first = step["cells"][0]["path"].get<std::string>();
        std::smatch m;
        REQUIRE(std::regex_search(first, m, item_pattern));
        frame_ = m[1];
        const std::string item = m[0];
        const std::string at_spec = step["at"].get<std::string>();
        const std::string name = at_spec.substr(at_spec.find("step=") + 5);
        if (m[4].matched) {
            const std::string phase = m[1].str() + ".phases[" + m[4].str() + "]";
            const auto iteration = static_cast<std::size_t>(std::stoul(m[5]));
            if (at_spec.find("phase=position") != std::string::npos)
                position_step(item, phase, iteration, name);
            else
                velocity_step(item, phase, iteration, name);
        } else {
            contact_step(item, name);
        }
    }

    // --- a prepared contact: steps 1-5 ------------------------------------------------------------------
    void contact_step(const std::string& c, const std::string& step) {
        const formats::json& bodies = k(at(c, "bodies"));
        if (step == "basis") {
            const Basis b = basis(vec(k(at(c, "normal"))));  // step 1
            put(at(c, "basis"), json_of(b.contact_to_world));
            put(at(c, "tangent_seed"), name(formats::tangent_seed_names, b.seed));
        } else if (step == "relative_position") {
            PerBody<Vec3> centres;
            for (std::size_t i = 0; i < 2; ++i)
                if (!bodies[i].is_null())
                    centres[i] = vec(k(at(at(at(frame_, "bodies_before"), bodies[i].get<std::size_t>()), "position")));
            const PerBody<Vec3> q = relative_position(vec(k(at(c, "point"))), centres);  // q_rel = q − p (1.8)
            for (std::size_t i = 0; i < 2; ++i)
                if (q[i]) put(at(at(c, "relative_position"), i), json_of(*q[i]));
        } else if (step == "delta_velocity_per_unit_impulse") {
            const UnitImpulseChain chain =
                delta_velocity_per_unit_impulse(vec(k(at(c, "normal"))), relative_positions(c, bodies), masses(bodies));
            for (std::size_t i = 0; i < 2; ++i) {
                if (!chain.bodies[i]) continue;
                const UnitImpulseResponse& r = *chain.bodies[i];
                put(at(at(c, "torque_per_unit_impulse"), i), json_of(r.torque_per_unit_impulse));
                put(at(at(c, "rotation_per_unit_impulse"), i), json_of(r.rotation_per_unit_impulse));
                put(at(at(c, "point_velocity_per_unit_impulse"), i), json_of(r.point_velocity_per_unit_impulse));
                put(at(at(c, "angular_component"), i), r.angular_component);
                put(at(at(c, "linear_component"), i), r.linear_component);
            }
            put(at(c, "delta_velocity_per_unit_impulse"), chain.delta_velocity_per_unit_impulse);
        } else if (step == "contact_velocity") {
            PerBody<BodyMotion> motion;
            for (std::size_t i = 0; i < 2; ++i) {
                if (bodies[i].is_null()) continue;
                const std::string body = at(at(frame_, "bodies_before"), bodies[i].get<std::size_t>());
                motion[i] = BodyMotion{vec(k(at(body, "velocity"))), vec(k(at(body, "angular_velocity"))),
                                       acceleration(bodies[i])};
            }
            const ContactVelocityTerms v = contact_velocity(basis_of(k(at(c, "basis"))), relative_positions(c, bodies),
                                                            motion, number("settings.duration"),
                                                            k("settings.tangential_acceleration_velocity").get<bool>());
            for (std::size_t i = 0; i < 2; ++i) {
                if (v.point_velocity[i]) put(at(at(c, "point_velocity"), i), json_of(*v.point_velocity[i]));
                if (v.tangential_acceleration_velocity[i])
                    put(at(at(c, "tangential_acceleration_velocity"), i),
                        json_of(*v.tangential_acceleration_velocity[i]));
            }
            put(at(c, "contact_velocity"), json_of(v.contact_velocity));
        } else if (step == "desired_delta_velocity") {
            desired(c, c, k(at(c, "contact_velocity"))[0].get<double>(), number(at(c, "restitution")),
                    vec(k(at(c, "normal"))), bodies, c);
        }
    }

    // Step 5 on a separating velocity, written under `out` (an item).
    DesiredDeltaVelocity desired(const std::string& out, const std::string& settings_item, double separating,
                                 double restitution, const Vec3& normal, const formats::json& bodies,
                                 const std::string& refinements_item) {
        VelocityRefinements refinements{};
        refinements.restitution_cutoff = number(at(refinements_item, "restitution_cutoff"));
        refinements.velocity_from_acceleration = k(at(settings_item, "velocity_from_acceleration_applied")).get<bool>();
        const DesiredDeltaVelocity d = desired_delta_velocity(separating, restitution, normal, accelerations(bodies),
                                                              number("settings.duration"), refinements);
        if (!out.empty()) {
            put(at(out, "separating_velocity"), d.separating_velocity);
            put(at(out, "restitution_cutoff_applied"), d.restitution_cutoff_applied);
            put(at(out, "restitution_used"), d.restitution_used);
            put(at(out, "velocity_from_acceleration"), d.velocity_from_acceleration);
            put(at(out, "desired_delta_velocity"), d.desired_delta_velocity);
        }
        return d;
    }

    // --- a position iteration: the choice, then step 8 -----------------------------------------------------
    void position_step(const std::string& p, const std::string& phase, std::size_t iteration, const std::string& step) {
        const formats::json& chosen = k(at(p, "contact"));
        const std::string c = contact_path(chosen);
        const formats::json& bodies = k(at(c, "bodies"));
        const Vec3 normal = vec(k(at(c, "normal")));
        const auto chain = [&] {
            return delta_velocity_per_unit_impulse(normal, relative_positions(c, bodies), masses(bodies));
        };
        const auto per_body = [&](const std::string& key, const std::string& object = {}) {
            PerBody<double> values;
            for (std::size_t i = 0; i < 2; ++i)
                if (!bodies[i].is_null()) values[i] = number(at(at(object.empty() ? p : at(p, object), key), i));
            return values;
        };
        if (step == "choice") {
            put(at(p, "penetration"), k(current(phase, iteration, std::string::npos, chosen, "penetration", "after")));
        } else if (step == "penetration_inertia") {
            const std::string method = k(at(p, "method")).get<std::string>();
            const double penetration = number(at(p, "penetration"));
            double amount = penetration;
            if (method == "relaxation") amount = number("settings.relaxation.fraction") * penetration;
            if (method == "velocity_based") amount = penetration - number(at(at(p, "rewind"), "removed_penetration"));
            put(at(p, "amount"), amount);
            PenetrationInertia inertia;
            if (method == "linear_projection") {
                // Linear projection never turns a body: its angular inertia counts as 0.
                inertia.penetration_inertia = 0.0;
                for (std::size_t i = 0; i < 2; ++i) {
                    if (bodies[i].is_null()) continue;
                    inertia.linear_inertia[i] = mass(bodies[i]).inverse_mass;
                    inertia.angular_inertia[i] = 0.0;
                    inertia.penetration_inertia += *inertia.linear_inertia[i];
                }
            } else {
                inertia = penetration_inertia(chain());
            }
            for (std::size_t i = 0; i < 2; ++i) {
                if (!inertia.linear_inertia[i]) continue;
                put(at(at(p, "linear_inertia"), i), *inertia.linear_inertia[i]);
                put(at(at(p, "angular_inertia"), i), *inertia.angular_inertia[i]);
            }
            put(at(p, "penetration_inertia"), inertia.penetration_inertia);
        } else if (step == "rewind") {
            // The bodies go back along their paths by the same time t = penetration / closing speed, at most the
            // frame (the chapter's velocity-based resolution).
            const std::string motion = phase.ends_with("[0]") ? "bodies_before" : "bodies_after";
            const std::string r = at(p, "rewind");
            PerBody<Vec3> velocity, spin;
            double separating = 0.0;
            for (std::size_t i = 0; i < 2; ++i) {
                if (bodies[i].is_null()) continue;
                const MassProperties m = mass(bodies[i]);
                const std::string body = at(at(frame_, motion), bodies[i].get<std::size_t>());
                velocity[i] = m.inverse_mass > 0.0 ? vec(k(at(body, "velocity"))) : Vec3::Zero();
                spin[i] = m.inverse_inertia_world.isZero(0.0) ? Vec3::Zero() : vec(k(at(body, "angular_velocity")));
                const Vec3 q = vec(k(at(at(c, "relative_position"), i)));
                separating += body_sign(static_cast<int>(i)) * (spin[i]->cross(q) + *velocity[i]).dot(normal);
            }
            const double closing = -separating;
            const double limit = number(at(r, "time_limit"));
            const double penetration = number(at(p, "penetration"));
            const double time = closing > 0.0 ? std::min(penetration / closing, limit) : 0.0;
            put(at(r, "closing_velocity"), closing);
            put(at(r, "time"), time);
            put(at(r, "removed_penetration"), closing * time);
            for (std::size_t i = 0; i < 2; ++i) {
                if (!velocity[i]) continue;
                put(at(at(r, "linear_change"), i), json_of(Vec3(-*velocity[i] * time)));
                put(at(at(r, "angular_change"), i), json_of(Vec3(-*spin[i] * time)));
            }
        } else if (step == "move_split") {
            PenetrationInertia inertia{per_body("linear_inertia"), per_body("angular_inertia"),
                                       number(at(p, "penetration_inertia"))};
            MoveSplit moves;
            if (inertia.penetration_inertia > 0.0) {
                moves = move_split(number(at(p, "amount")), inertia);
            } else {
                for (std::size_t i = 0; i < 2; ++i)
                    if (!bodies[i].is_null()) moves.linear_move[i] = moves.angular_move[i] = 0.0;
            }
            const std::string limit = at(p, "angular_limit");
            if (has(at(limit, "policy"))) {
                const auto policy = named(formats::angular_limit_policy_names, k(at(limit, "policy")));
                const OrientationUpdate update =
                    policy == AngularLimitPolicy::angle
                        ? named(formats::orientation_update_names, k("settings.orientation_update"))
                        : OrientationUpdate::first_order;
                const LimitedMoves limited = angular_limit(moves, {policy, number(at(limit, "factor"))}, normal,
                                                           relative_positions(c, bodies), chain(), update);
                const AngularLimit& a = limited.limit;
                moves = limited.moves;
                for (std::size_t i = 0; i < 2; ++i) {
                    if (a.maximum[i]) put(at(at(limit, "maximum"), i), *a.maximum[i]);
                    if (a.applied[i]) put(at(at(limit, "applied"), i), *a.applied[i]);
                    if (a.before.linear_move[i]) put(at(at(limit, "linear_move_before"), i), *a.before.linear_move[i]);
                    if (a.before.angular_move[i])
                        put(at(at(limit, "angular_move_before"), i), *a.before.angular_move[i]);
                }
            }
            for (std::size_t i = 0; i < 2; ++i) {
                if (!moves.linear_move[i]) continue;
                put(at(at(at(p, "move_split"), "linear_move"), i), *moves.linear_move[i]);
                put(at(at(at(p, "move_split"), "angular_move"), i), *moves.angular_move[i]);
            }
        } else if (step == "position_change") {
            const MoveSplit moves{per_body("linear_move", "move_split"), per_body("angular_move", "move_split")};
            PositionChange change = position_change(moves, normal, chain());
            const std::string r = at(p, "rewind");
            const bool rewound = k(at(p, "method")) == "velocity_based";
            for (std::size_t i = 0; i < 2; ++i) {
                if (!change.linear_change[i]) continue;
                if (rewound) {
                    *change.linear_change[i] += vec(k(at(at(r, "linear_change"), i)));
                    *change.angular_change[i] += vec(k(at(at(r, "angular_change"), i)));
                }
                put(at(at(at(p, "position_change"), "linear_change"), i), json_of(*change.linear_change[i]));
                put(at(at(at(p, "position_change"), "angular_change"), i), json_of(*change.angular_change[i]));
            }
        } else if (step == "updates") {
            const std::string updates = at(p, "updates");
            for (std::size_t u = 0; has(at(at(updates, u), "contact")); ++u) {
                const auto [update, other, slot, moved, o] = update_at(updates, u, bodies);
                const double before = number(current(phase, iteration, u, other, "penetration", "after"));
                // The moved point of the other contact along its normal: (Δp + Δθ × q_rel) · n.
                const Vec3 q = vec(k(at(at(o, "relative_position"), slot)));
                const Vec3 move = vec(k(at(at(at(p, "position_change"), "linear_change"), moved))) +
                                  vec(k(at(at(at(p, "position_change"), "angular_change"), moved))).cross(q);
                const double delta = -body_sign(static_cast<int>(slot)) * move.dot(vec(k(at(o, "normal"))));
                put(at(update, "delta"), delta);
                put(at(update, "after"), before + delta);
            }
        }
    }

    // --- a velocity iteration: the choice, then steps 4-7 -------------------------------------------------
    // AVBD's force (Eq. 11) from the lambda, k and C* a visit read, and its dual update's new lambda (its force).
    Vec3 avbd_force(const std::string& rows, const std::string& friction) const {
        const formats::json& k_json = k(at(rows, "stiffness"));
        const Stiffness stiffness{k_json[0].get<double>(), k_json[1].get<double>()};
        return contact_force(vec(k(at(rows, "lambda"))), stiffness, vec(k(at(rows, "constraint"))), number(friction))
            .force;
    }

    // Whether AVBD's step `step` of iteration `v` was worked out here.
    bool avbd_step(const std::string& v, const std::string& step) {
        if (step == "force" && has(at(at(at(v, "gathered"), 0), "contact"))) {
            for (std::size_t i = 0; has(at(at(at(v, "gathered"), i), "contact")); ++i) {
                const std::string rows = at(at(v, "gathered"), i);
                put(at(rows, "force"), json_of(avbd_force(rows, at(rows, "friction"))));
            }
            return true;
        }
        if (step == "force" && has(at(v, "lambda"))) {
            put(at(v, "force"), json_of(avbd_force(v, at(v, "friction"))));
            return true;
        }
        if (step == "dual_update") {
            put(at(at(v, "dual_update"), "lambda"), k(at(v, "force")));  // lambda <- F (Eq. 11)
            return true;
        }
        return false;
    }

    void velocity_step(const std::string& v, const std::string& phase, std::size_t iteration, const std::string& step) {
        if (avbd_step(v, step)) return;
        const formats::json& chosen = k(at(v, "contact"));
        const std::string c = contact_path(chosen);
        const formats::json& bodies = k(at(c, "bodies"));
        if (step == "contact_velocity") {
            put(at(v, "contact_velocity"),
                k(current(phase, iteration, std::string::npos, chosen, "contact_velocity", "after")));
        } else if (step == "desired_delta_velocity") {
            const Basis b = basis_of(k(at(c, "basis")));
            desired(v, v, k(at(v, "contact_velocity"))[0].get<double>(), number(at(v, "restitution")), b.normal(),
                    bodies, v);
        } else if (step == "impulse") {
            const Impulse g = calculate_impulse(
                basis_of(k(at(c, "basis"))), relative_positions(c, bodies), masses(bodies),
                vec(k(at(v, "contact_velocity"))), number(at(v, "desired_delta_velocity")),
                number(at(c, "delta_velocity_per_unit_impulse")), number(at(c, "friction")), sliding_friction());
            put(at(v, "impulse_model"), name(formats::impulse_model_names, g.impulse_model));
            if (g.friction_solve) {
                const FrictionSolve& s = *g.friction_solve;
                const std::string f = at(v, "friction_solve");
                put(at(f, "delta_velocity_matrix"), json_of(s.delta_velocity_matrix));
                put(at(f, "target_delta_velocity"), json_of(s.target_delta_velocity));
                put(at(f, "solvable"), s.solvable);
                put(at(f, "static_impulse"), json_of(s.static_impulse));
                put(at(f, "tangential_impulse"), s.tangential_impulse);
                put(at(f, "cone_limit"), s.cone_limit);
                if (s.sliding_direction)
                    put(at(f, "sliding_direction"),
                        formats::json::array({s.sliding_direction->x(), s.sliding_direction->y()}));
                if (s.sliding_normal_response) put(at(f, "sliding_normal_response"), *s.sliding_normal_response);
            }
            put(at(v, "impulse"), json_of(g.impulse));
            put(at(v, "impulse_world"), json_of(g.impulse_world));
        } else if (step == "velocity_change") {
            const VelocityChange change =
                velocity_change(vec(k(at(v, "impulse_world"))), relative_positions(c, bodies), masses(bodies));
            for (std::size_t i = 0; i < 2; ++i) {
                if (!change.velocity_change[i]) continue;
                put(at(at(v, "impulsive_torque"), i), json_of(*change.impulsive_torque[i]));
                put(at(at(v, "velocity_change"), i), json_of(*change.velocity_change[i]));
                put(at(at(v, "rotation_change"), i), json_of(*change.rotation_change[i]));
            }
        } else if (step == "updates") {
            const std::string updates = at(v, "updates");
            for (std::size_t u = 0; has(at(at(updates, u), "contact")); ++u) {
                const auto [update, other, slot, moved, o] = update_at(updates, u, bodies);
                const Vec3 before = vec(k(current(phase, iteration, u, other, "contact_velocity", "after")));
                // The changed point of the other contact, in its contact coordinates (9.5): ±Cᵀ(Δṗ + Δθ̇ × q_rel).
                const Basis b = basis_of(k(at(o, "basis")));
                const Vec3 q = vec(k(at(at(o, "relative_position"), slot)));
                const Vec3 change =
                    vec(k(at(at(v, "velocity_change"), moved))) + vec(k(at(at(v, "rotation_change"), moved))).cross(q);
                const Vec3 delta = body_sign(static_cast<int>(slot)) * to_contact(b, change);
                const Vec3 after = before + delta;
                const double restitution =
                    other == chosen ? number(at(v, "restitution")) : number(at(o, "restitution"));
                const DesiredDeltaVelocity d =
                    desired("", v, after.x(), restitution, b.normal(), k(at(o, "bodies")), v);
                put(at(update, "delta"), json_of(delta));
                put(at(update, "after"), json_of(after));
                put(at(update, "desired_delta_velocity_after"), d.desired_delta_velocity);
            }
        }
    }

    const formats::json& sheet_;
    const formats::json& reference_;
    std::map<std::string, formats::json> known_;
    std::map<std::string, formats::json> out_;  // the step being worked out
    std::string frame_;
};

}  // namespace

namespace impulse::test {

HandWork work_by_hand(const formats::json& sheet, const formats::json& reference) {
    HandWorker worker(sheet, reference);
    std::vector<std::string> undone = worker.work();
    return {worker.filled(), std::move(undone)};
}

}  // namespace impulse::test
