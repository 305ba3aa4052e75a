// ODE (libode-dev 0.16, double precision): a dWorld stepped by its iterative QuickStep solver, a hash space for
// collision, contact joints made each step from dCollide's points. docs/bench.md, "Other engines", states every
// setting fixed here and why.

#include "bench/adapters/engine_adapter.hpp"

#include <ode/ode.h>
#include <ode/version.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>

namespace impulse::bench {

namespace {

static_assert(sizeof(dReal) == sizeof(double), "the ODE adapter needs ODE's double-precision build");

// Box-box gives up to 8 points (ODE's dBoxBox), box-plane up to 4 here, sphere-anything 1.
constexpr int max_points_per_pair = 8;
// No bounce below 0.2 m/s (Bullet's default threshold, so the two engines agree on when a contact rests).
constexpr double bounce_velocity = 0.2;

// ODE's library state (its collision tables) is set up once per process; nothing is torn down, as the
// library is used until the program ends.
void initialise_ode() {
    static std::once_flag once;
    std::call_once(once, [] { dInitODE2(0); });
}

class OdeWorld final : public EngineWorld {
public:
    OdeWorld(const Scene& scene, int iterations) : dt_(scene.settings.duration) {
        initialise_ode();
        world_ = dWorldCreate();
        space_ = dHashSpaceCreate(nullptr);
        contact_group_ = dJointGroupCreate(0);
        const Vec3& g = scene.world.gravity;
        dWorldSetGravity(world_, g.x(), g.y(), g.z());
        dWorldSetQuickStepNumIterations(world_, iterations);  // N: sweeps of QuickStep's SOR solver
        dWorldSetAutoDisableFlag(world_, 0);                  // sleeping off
        // ODE multiplies a velocity by (1 - scale) each step; the scene states the share kept per second.
        dWorldSetLinearDamping(world_, damping_per_step(scene.world.linear_damping, dt_));
        dWorldSetAngularDamping(world_, damping_per_step(scene.world.angular_damping, dt_));
        // ERP and CFM stay ODE's own (0.2 and 1e-10 in double): a fifth of the penetration corrected per step,
        // a nearly hard contact.

        materials_.reserve(scene.bodies.size() + 1);
        if (scene.ground) {
            const HalfSpace& plane = scene.ground->plane;
            // dCreatePlane: a x + b y + c z = d with (a, b, c) the unit normal out of the solid, as our half space.
            const dGeomID geom =
                dCreatePlane(space_, plane.normal.x(), plane.normal.y(), plane.normal.z(), plane.offset);
            materials_.push_back(scene.materials.at(scene.ground->material));
            dGeomSetData(geom, &materials_.back());
        }
        bodies_.reserve(scene.bodies.size());
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            const RigidBody& b = scene.bodies[i];
            dGeomID geom = nullptr;
            if (scene.shapes[i]) {
                if (const auto* sphere = std::get_if<Sphere>(&*scene.shapes[i])) {
                    geom = dCreateSphere(space_, sphere->radius);
                } else {
                    const Vec3 size = 2.0 * std::get<Box>(*scene.shapes[i]).half_size;  // ODE takes full lengths
                    geom = dCreateBox(space_, size.x(), size.y(), size.z());
                }
                materials_.push_back(scene.materials.at(scene.body_materials[i]));
                dGeomSetData(geom, &materials_.back());
            }
            const dQuaternion q{b.orientation.w(), b.orientation.x(), b.orientation.y(), b.orientation.z()};
            if (b.inverse_mass == 0.0) {
                // Immovable: a geom without a body, fixed where the scene puts it.
                bodies_.push_back(nullptr);
                if (geom) {
                    dGeomSetPosition(geom, b.position.x(), b.position.y(), b.position.z());
                    dGeomSetQuaternion(geom, q);
                }
                static_poses_.push_back({b.position, b.orientation});
                continue;
            }
            static_poses_.push_back({});
            const dBodyID body = dBodyCreate(world_);
            dMass mass;
            const Vec3 inertia = principal_inertia_of(b);
            // The body's origin is its centre of mass (c = 0), principal axes along the body's axes.
            dMassSetParameters(&mass, mass_of(b), 0, 0, 0, inertia.x(), inertia.y(), inertia.z(), 0, 0, 0);
            dBodySetMass(body, &mass);
            dBodySetPosition(body, b.position.x(), b.position.y(), b.position.z());
            dBodySetQuaternion(body, q);
            dBodySetLinearVel(body, b.velocity.x(), b.velocity.y(), b.velocity.z());
            dBodySetAngularVel(body, b.angular_velocity.x(), b.angular_velocity.y(), b.angular_velocity.z());
            if (geom) dGeomSetBody(geom, body);
            bodies_.push_back(body);
        }
    }

    ~OdeWorld() override {
        dJointGroupDestroy(contact_group_);
        dSpaceDestroy(space_);  // destroys its geoms
        dWorldDestroy(world_);  // destroys its bodies
    }

    OdeWorld(const OdeWorld&) = delete;
    OdeWorld& operator=(const OdeWorld&) = delete;

    void step() override {
        contacts_ = 0;
        dSpaceCollide(space_, this, &OdeWorld::near_callback);
        dWorldQuickStep(world_, dt_);
        dJointGroupEmpty(contact_group_);  // contact joints live for one step
    }

    void read_bodies(std::vector<RigidBody>& ioBodies) const override {
        for (std::size_t i = 0; i < ioBodies.size(); ++i) {
            const dBodyID body = bodies_[i];
            if (!body) {
                ioBodies[i].position = static_poses_[i].position;
                ioBodies[i].orientation = static_poses_[i].orientation;
                continue;
            }
            const dReal* p = dBodyGetPosition(body);    // the body's origin, which is its centre of mass
            const dReal* q = dBodyGetQuaternion(body);  // [w, x, y, z], as ours are written
            const dReal* v = dBodyGetLinearVel(body);
            const dReal* w = dBodyGetAngularVel(body);  // world frame
            ioBodies[i].position = {p[0], p[1], p[2]};
            ioBodies[i].orientation = Quat(q[0], q[1], q[2], q[3]);
            ioBodies[i].velocity = {v[0], v[1], v[2]};
            ioBodies[i].angular_velocity = {w[0], w[1], w[2]};
        }
    }

    int touching_contacts() const override { return contacts_; }

private:
    struct Pose {
        Vec3 position = Vec3::Zero();
        Quat orientation = Quat::Identity();
    };

    static void near_callback(void* data, dGeomID a, dGeomID b) { static_cast<OdeWorld*>(data)->collide(a, b); }

    void collide(dGeomID a, dGeomID b) {
        const dBodyID body_a = dGeomGetBody(a), body_b = dGeomGetBody(b);
        if (!body_a && !body_b) return;  // two immovable things
        std::array<dContact, max_points_per_pair> points{};
        const int n = dCollide(a, b, max_points_per_pair, &points[0].geom, sizeof(dContact));
        const Material& ma = *static_cast<const Material*>(dGeomGetData(a));
        const Material& mb = *static_cast<const Material*>(dGeomGetData(b));
        const Material combined = combine(ma, mb);  // restitution max, friction sqrt(mu_a mu_b), as ours
        for (int i = 0; i < n; ++i) {
            dContact& contact = points[static_cast<std::size_t>(i)];
            // Approx1: Coulomb friction (the limit is mu times the normal force) on a pyramid of two directions.
            contact.surface.mode = dContactApprox1 | (combined.restitution > 0.0 ? dContactBounce : 0);
            contact.surface.mu = combined.friction;
            contact.surface.bounce = combined.restitution;
            contact.surface.bounce_vel = bounce_velocity;
            const dJointID joint = dJointCreateContact(world_, contact_group_, &contact);
            dJointAttach(joint, body_a, body_b);
        }
        contacts_ += n;  // dCollide returns touching or penetrating points only (depth >= 0)
    }

    double dt_;
    dWorldID world_ = nullptr;
    dSpaceID space_ = nullptr;
    dJointGroupID contact_group_ = nullptr;
    std::vector<Material> materials_;  // each geom's, pointed to by its data (reserved: never reallocated)
    std::vector<dBodyID> bodies_;      // per scene body; null for an immovable one
    std::vector<Pose> static_poses_;   // per scene body: where an immovable one stays
    int contacts_ = 0;
};

std::unique_ptr<EngineWorld> make_ode_world(const Scene& scene, int iterations) {
    check_scene_for_engine(scene, "ode");
    return std::make_unique<OdeWorld>(scene, iterations);
}

}  // namespace

extern const EngineRow ode_engine;
const EngineRow ode_engine{"ode", "dWorldSetQuickStepNumIterations", "ODE " dODE_VERSION " (double)", make_ode_world};

}  // namespace impulse::bench
