// MuJoCo 2.2 (libmujoco-dev; mjtNum is double): the scene written as an MJCF model (one free body per movable
// scene body, the ground a plane), loaded from memory, stepped with mj_step. docs/bench.md, "Other engines",
// states every setting fixed here and why.

#include "bench/adapters/engine_adapter.hpp"

#include "formats/input_error.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

namespace impulse::bench {

namespace {

static_assert(sizeof(mjtNum) == sizeof(double), "MuJoCo computes in double");

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

std::string vec(const Vec3& v) {
    return num(v.x()) + " " + num(v.y()) + " " + num(v.z());
}

// MuJoCo's contacts are soft: a spring-damper in the constraint's space with damping ratio `dampratio` and time
// constant `timeconst` (solref). A damped spring that lets go when it is back at rest length returns
// c = exp(-pi zeta / sqrt(1 - zeta^2)) of the speed it struck with, so restitution c needs
// zeta = -ln c / sqrt(pi^2 + ln^2 c); c = 0 is critical damping (zeta = 1), no bounce.
double damping_ratio_for(double restitution) {
    if (restitution <= 0.0) return 1.0;
    const double l = std::log(std::min(restitution, 0.99));
    return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

// The time constant: for a resting contact (zeta = 1) the stiffest MuJoCo allows at this step, 2 dt (its
// "refsafe" floor). For a bouncing one, stiffer than that would let the spring's half period fit in about one
// step, and the discrete bounce would not follow the spring's: the time constant is chosen so that half a
// period spans 4 steps (omega = 1 / (dmax timeconst zeta), dmax = 0.95 being solimp's default).
double time_constant_for(double restitution, double dt) {
    const double zeta = damping_ratio_for(restitution);
    if (zeta >= 1.0) return 2.0 * dt;
    const double omega = std::numbers::pi / (4.0 * dt) / std::sqrt(1.0 - zeta * zeta);
    return std::max(2.0 * dt, 1.0 / (0.95 * zeta * omega));
}

// The attributes a contact of material `m` (or a pair's combined material) takes: friction only along the
// surface (condim 3, no torsion or rolling), the soft contact above, no margin.
std::string contact_attributes(const Material& m, double dt, bool pair) {
    const std::string mu = num(m.friction);
    return " condim=\"3\" friction=\"" + (pair ? mu + " " + mu + " 0 0 0" : mu + " 0 0") + "\" solref=\"" +
           num(time_constant_for(m.restitution, dt)) + " " + num(damping_ratio_for(m.restitution)) + "\" margin=\"0\"";
}

// The MJCF text of `scene`. Materials: MuJoCo mixes two geoms' friction by the larger and their solref by a
// weighted mean, not as we combine. So each material collides only with itself through its own contype bit, and
// every pair of geoms of different materials is an explicit <pair> with the combined material (scene.hpp).
std::string model_text(const Scene& scene, int iterations) {
    const double dt = scene.settings.duration;
    std::map<std::string, int> material_bit;
    auto bit_of = [&](const std::string& name) {
        const auto [it, added] = material_bit.emplace(name, static_cast<int>(material_bit.size()));
        if (it->second >= 31)
            throw formats::InputError("materials",
                                      "mujoco runs at most 31 materials that touch (one contact bit each)");
        return it->second;
    };
    auto geom_material = [&](const std::string& name) {
        const int bit = bit_of(name);
        return " contype=\"" + std::to_string(1u << bit) + "\" conaffinity=\"" + std::to_string(1u << bit) + "\"" +
               contact_attributes(scene.materials.at(name), dt, false);
    };

    // Room for contacts and constraint rows: 12 points a body (a box on a box gives up to 8, and a pyramid's box
    // rests on two) and 4 rows a point (a pyramidal cone: two directions, each both ways). MuJoCo 2.2 keeps an
    // njmax x njmax matrix (efc_AR), so a scene needing more than 2 GB of it is refused rather than run out of
    // memory.
    const long contact_capacity = 12L * static_cast<long>(scene.bodies.size()) + 64;
    const long rows = 4 * contact_capacity;
    if (rows * rows * 12 > (2L << 30))
        throw std::runtime_error("mujoco 2.2 would need " + std::to_string(rows * rows * 12 >> 20) +
                                 " MB for its constraint matrix (njmax = " + std::to_string(rows) +
                                 " rows squared): too many bodies");
    std::string xml = "<mujoco model=\"impulse-lab\">\n<compiler angle=\"radian\"/>\n<size nconmax=\"" +
                      std::to_string(contact_capacity) + "\" njmax=\"" + std::to_string(rows) + "\"/>\n";
    // MuJoCo's default pyramidal friction cone: with Newton at this step its elliptic cone leaves a stack jittering.
    xml += "<option timestep=\"" + num(dt) + "\" gravity=\"" + vec(scene.world.gravity) + "\" iterations=\"" +
           std::to_string(iterations) + "\" integrator=\"Euler\" cone=\"pyramidal\"/>\n<worldbody>\n";
    std::vector<std::pair<std::string, std::string>> geoms;  // (geom name, material) for the explicit pairs
    if (scene.ground) {
        const HalfSpace& plane = scene.ground->plane;
        // A plane's normal is its local z: zaxis turns it onto ours; n . x = offset through offset n.
        xml += "<geom name=\"ground\" type=\"plane\" size=\"0 0 1\" pos=\"" + vec(plane.offset * plane.normal) +
               "\" zaxis=\"" + vec(plane.normal) + "\"" + geom_material(scene.ground->material) + "/>\n";
        geoms.emplace_back("ground", scene.ground->material);
    }
    for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i) {
        const RigidBody& b = scene.bodies[static_cast<std::size_t>(i)];
        const std::string name = "b" + std::to_string(i);
        const Quat& q = b.orientation;
        xml += "<body name=\"" + name + "\" pos=\"" + vec(b.position) + "\" quat=\"" + num(q.w()) + " " + num(q.x()) +
               " " + num(q.y()) + " " + num(q.z()) + "\">\n";
        if (b.inverse_mass > 0.0)  // the body frame is the centre of mass, its axes the principal axes
            xml += "<freejoint/><inertial pos=\"0 0 0\" mass=\"" + num(mass_of(b)) + "\" diaginertia=\"" +
                   vec(principal_inertia_of(b)) + "\"/>\n";
        if (const auto& shape = scene.shapes[static_cast<std::size_t>(i)]) {
            const std::string& material = scene.body_materials[static_cast<std::size_t>(i)];
            xml += "<geom name=\"" + name + "\" ";
            if (const auto* sphere = std::get_if<Sphere>(&*shape))
                xml += "type=\"sphere\" size=\"" + num(sphere->radius) + "\"";
            else
                xml += "type=\"box\" size=\"" + vec(std::get<Box>(*shape).half_size) + "\"";
            xml += " mass=\"0\"" + geom_material(material) + "/>\n";
            geoms.emplace_back(name, material);
        }
        xml += "</body>\n";
    }
    xml += "</worldbody>\n<contact>\n";
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < geoms.size(); ++i)
        for (std::size_t j = i + 1; j < geoms.size(); ++j) {
            if (geoms[i].second == geoms[j].second) continue;
            if (++pairs > 10000)
                throw formats::InputError("materials",
                                          "mujoco: more than 10000 pairs of bodies of different materials");
            const Material combined = combine(scene.materials.at(geoms[i].second), scene.materials.at(geoms[j].second));
            xml += "<pair geom1=\"" + geoms[i].first + "\" geom2=\"" + geoms[j].first + "\"" +
                   contact_attributes(combined, dt, true) + "/>\n";
        }
    xml += "</contact>\n</mujoco>\n";
    return xml;
}

class MujocoWorld final : public EngineWorld {
public:
    MujocoWorld(const Scene& scene, int iterations) {
        const std::string xml = model_text(scene, iterations);
        auto vfs = std::make_unique<mjVFS>();  // large (its file table): not on the stack
        mj_defaultVFS(vfs.get());
        const char* file = "scene.xml";
        mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(xml.size()));
        std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[mj_findFileVFS(vfs.get(), file)]));
        char error[1000] = "";
        model_ = mj_loadXML(file, vfs.get(), error, sizeof error);
        mj_deleteVFS(vfs.get());
        if (!model_) throw std::runtime_error(std::string("mujoco could not load the scene's model: ") + error);
        data_ = mj_makeData(model_);
        // Damping: MuJoCo's is a joint property, per second; none unless the scene asks for it.
        if (scene.world.linear_damping != 1.0 || scene.world.angular_damping != 1.0)
            throw formats::InputError("world", "mujoco: the scene's damping is not mapped (MuJoCo damps joints)");

        // Each movable body's free joint: qpos (x, y, z, qw, qx, qy, qz), qvel (v in the world frame, omega in the
        // body's frame).
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            const RigidBody& b = scene.bodies[i];
            const int body_id = static_cast<int>(i) + 1;  // body 0 is the world
            const int joint = model_->body_jntadr[body_id];
            free_joints_.push_back(joint);
            static_poses_.push_back({b.position, b.orientation});
            if (joint < 0) continue;
            mjtNum* v = data_->qvel + model_->jnt_dofadr[joint];
            const Vec3 local_omega = b.orientation.conjugate() * b.angular_velocity;
            for (int k = 0; k < 3; ++k) {
                v[k] = b.velocity[k];
                v[3 + k] = local_omega[k];
            }
        }
    }

    ~MujocoWorld() override {
        mj_deleteData(data_);
        mj_deleteModel(model_);
    }

    MujocoWorld(const MujocoWorld&) = delete;
    MujocoWorld& operator=(const MujocoWorld&) = delete;

    void step() override {
        mj_step(model_, data_);
        for (const int w : {mjWARN_CONTACTFULL, mjWARN_CNSTRFULL})
            if (data_->warning[w].number > 0)
                throw std::runtime_error("mujoco ran out of room for contacts or constraints (warning " +
                                         std::to_string(w) + ")");
        // A state MuJoCo finds non-finite or too large it does not keep: it resets the whole simulation to the
        // model's start and warns. For the bench that is a run that became NaN, not one that began again.
        for (const int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC})
            if (data_->warning[w].number > 0) blew_up_ = true;
    }

    void read_bodies(std::vector<RigidBody>& ioBodies) const override {
        for (std::size_t i = 0; i < ioBodies.size(); ++i) {
            const int joint = free_joints_[i];
            if (joint < 0) {
                ioBodies[i].position = static_poses_[i].first;
                ioBodies[i].orientation = static_poses_[i].second;
                continue;
            }
            if (blew_up_) {
                const double nan = std::numeric_limits<double>::quiet_NaN();
                ioBodies[i].position = Vec3::Constant(nan);
                ioBodies[i].velocity = Vec3::Constant(nan);
                continue;
            }
            const mjtNum* p = data_->qpos + model_->jnt_qposadr[joint];
            const mjtNum* v = data_->qvel + model_->jnt_dofadr[joint];
            ioBodies[i].position = {p[0], p[1], p[2]};
            ioBodies[i].orientation = Quat(p[3], p[4], p[5], p[6]).normalized();  // MuJoCo writes [w, x, y, z]
            ioBodies[i].velocity = {v[0], v[1], v[2]};
            ioBodies[i].angular_velocity = ioBodies[i].orientation * Vec3(v[3], v[4], v[5]);  // body -> world
        }
    }

    int touching_contacts() const override {
        int count = 0;
        for (int c = 0; c < data_->ncon; ++c)
            if (data_->contact[c].dist <= 0.0) ++count;
        return count;
    }

private:
    mjModel* model_ = nullptr;
    mjData* data_ = nullptr;
    std::vector<int> free_joints_;  // per scene body: its free joint, -1 for an immovable body
    std::vector<std::pair<Vec3, Quat>> static_poses_;
    bool blew_up_ = false;  // MuJoCo reset a non-finite state: every body reads as NaN from then on
};

std::unique_ptr<EngineWorld> make_mujoco_world(const Scene& scene, int iterations) {
    check_scene_for_engine(scene, "mujoco");
    return std::make_unique<MujocoWorld>(scene, iterations);
}

}  // namespace

extern const EngineRow mujoco_engine;
const EngineRow mujoco_engine{"mujoco", "mjOption::iterations", "MuJoCo 2.2.2", make_mujoco_world};

}  // namespace impulse::bench
