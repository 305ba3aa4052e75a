// Bullet 3 (libbullet-dev, the double-precision build `bullet-float64`): a btDiscreteDynamicsWorld with its
// sequential-impulse solver, one btRigidBody per scene body. docs/bench.md, "Other engines", states every
// setting fixed here and why.

#include "bench/adapters/engine_adapter.hpp"

#include "formats/input_error.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace impulse::bench {

namespace {

static_assert(sizeof(btScalar) == sizeof(double), "the Bullet adapter needs Bullet's double-precision build");

btVector3 to_bullet(const Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

Vec3 from_bullet(const btVector3& v) {
    return {v.x(), v.y(), v.z()};
}

// Bullet combines materials through two global hooks (product by default). Ours: the bouncier surface decides,
// friction is the geometric mean (scene.hpp, combine). Stateless functions, so setting them is idempotent.
btScalar combined_restitution(const btCollisionObject* a, const btCollisionObject* b) {
    return std::max(a->getRestitution(), b->getRestitution());
}

btScalar combined_friction(const btCollisionObject* a, const btCollisionObject* b) {
    return std::sqrt(a->getFriction() * b->getFriction());
}

class BulletWorld final : public EngineWorld {
public:
    BulletWorld(const Scene& scene, int iterations)
        : dt_(scene.settings.duration),
          dispatcher_(&configuration_),
          world_(&dispatcher_, &broad_phase_, &solver_, &configuration_) {
        gCalculateCombinedRestitutionCallback = combined_restitution;
        gCalculateCombinedFrictionCallback = combined_friction;
        world_.setGravity(to_bullet(scene.world.gravity));
        btContactSolverInfo& info = world_.getSolverInfo();
        info.m_numIterations = iterations;  // N: sweeps of the sequential-impulse solver
        // Bullet resolves penetration two ways: contacts deeper than m_splitImpulsePenetrationThreshold by the
        // split impulse (a separate velocity that moves the bodies and is then dropped, so it adds no energy),
        // shallower ones by Baumgarte (ERP2 x depth / dt added to the contact's target velocity, i.e. energy).
        // Bullet's default threshold, 4 cm, leaves an impact's penetration to Baumgarte: a ball that sinks 3 cm in
        // one 1/60 s frame leaves with 0.8 x 0.03 x 60 = 1.4 m/s on top of its bounce. The threshold is one frame
        // of free fall, g dt^2 (2.7 mm at 1/60 s): an impact sinks deeper and is pushed out by the split impulse; a
        // resting contact, which gravity presses in by at most that much a frame, keeps Bullet's Baumgarte, which
        // is what holds its stacks (threshold 0 collapses stack_10 at every N; docs/bench.md, "Other engines").
        info.m_splitImpulse = 1;
        info.m_splitImpulsePenetrationThreshold = -scene.world.gravity.norm() * dt_ * dt_;
        // Both ways remove ERP2 of the depth a step: 0.8, Bullet 2's default (3.24's is 0.2, with which stack_10
        // and pyramid_20 miss their 5 cm target at N = 32; docs/bench.md).
        info.m_erp2 = 0.8;
        info.m_restitutionVelocityThreshold = 0.2;  // Bullet's default: no bounce below 0.2 m/s

        if (scene.ground) {
            const HalfSpace& plane = scene.ground->plane;
            shapes_.push_back(std::make_unique<btStaticPlaneShape>(to_bullet(plane.normal), plane.offset));
            add_body(0.0, btVector3(0, 0, 0), *shapes_.back(), btTransform::getIdentity(),
                     scene.materials.at(scene.ground->material), scene.world);
            ground_ = true;
        }
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            const RigidBody& b = scene.bodies[i];
            if (!scene.shapes[i])
                shapes_.push_back(std::make_unique<btEmptyShape>());
            else if (const auto* sphere = std::get_if<Sphere>(&*scene.shapes[i]))
                shapes_.push_back(std::make_unique<btSphereShape>(sphere->radius));
            else
                shapes_.push_back(std::make_unique<btBoxShape>(to_bullet(std::get<Box>(*scene.shapes[i]).half_size)));
            const btTransform pose(
                btQuaternion(b.orientation.x(), b.orientation.y(), b.orientation.z(), b.orientation.w()),
                to_bullet(b.position));
            btRigidBody& body = add_body(mass_of(b), to_bullet(principal_inertia_of(b)), *shapes_.back(), pose,
                                         scene.materials.at(scene.body_materials[i]), scene.world);
            body.setLinearVelocity(to_bullet(b.velocity));
            body.setAngularVelocity(to_bullet(b.angular_velocity));
        }
    }

    void step() override {
        world_.stepSimulation(dt_, 0);  // maxSubSteps 0: one step of exactly dt (no fixed internal clock)
    }

    void read_bodies(std::vector<RigidBody>& ioBodies) const override {
        for (std::size_t i = 0; i < ioBodies.size(); ++i) {
            const btRigidBody& body = *bodies_[i + (ground_ ? 1 : 0)];
            // Bullet's body origin is its centre of mass (the shapes are centred on it, as ours are).
            ioBodies[i].position = from_bullet(body.getCenterOfMassPosition());
            const btQuaternion q = body.getOrientation();  // stored (x, y, z, w)
            ioBodies[i].orientation = Quat(q.w(), q.x(), q.y(), q.z());
            ioBodies[i].velocity = from_bullet(body.getLinearVelocity());
            ioBodies[i].angular_velocity = from_bullet(body.getAngularVelocity());  // world frame
        }
    }

    int touching_contacts() const override {
        int count = 0;
        for (int m = 0; m < dispatcher_.getNumManifolds(); ++m) {
            const btPersistentManifold* manifold = dispatcher_.getManifoldByIndexInternal(m);
            for (int p = 0; p < manifold->getNumContacts(); ++p)
                if (manifold->getContactPoint(p).getDistance() <= 0.0) ++count;
        }
        return count;
    }

private:
    btRigidBody& add_body(double mass, const btVector3& inertia, btCollisionShape& shape, const btTransform& pose,
                          const Material& material, const WorldSettings& world) {
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, &shape, inertia);
        info.m_startWorldTransform = pose;
        info.m_friction = material.friction;
        info.m_restitution = material.restitution;
        // Bullet keeps (1 - damping)^dt of a velocity per step; the scene states the share kept per second.
        info.m_linearDamping = 1.0 - world.linear_damping;
        info.m_angularDamping = 1.0 - world.angular_damping;
        bodies_.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody& body = *bodies_.back();
        body.setActivationState(DISABLE_DEACTIVATION);  // sleeping off: a resting stack is still solved
        // A bouncy body's contacts are solved only once the shapes touch. Bullet keeps contact points from a gap
        // of 0.02 x the shape's bounding radius (1.7 cm for a ball of radius 0.5 m) and solves them as speculative
        // contacts, aiming at the separating speed c |v| - gap / dt: restitution then no longer returns c of the
        // closing speed (at 1 ms steps a ball stops on the ground without bouncing). Bullet keeps the smaller
        // threshold of the two bodies, so a contact whose combined restitution is above 0 (the larger of the two)
        // touches first; contacts of restitution 0 stay speculative, as Bullet ships them.
        if (material.restitution > 0.0) body.setContactProcessingThreshold(0.0);
        world_.addRigidBody(&body);
        return body;
    }

    double dt_;
    bool ground_ = false;
    // Destroyed in reverse: the world first (it still needs its bodies' broad-phase handles), then the bodies.
    btDefaultCollisionConfiguration configuration_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broad_phase_;
    btSequentialImpulseConstraintSolver solver_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;
    btDiscreteDynamicsWorld world_;
};

std::unique_ptr<EngineWorld> make_bullet_world(const Scene& scene, int iterations) {
    check_scene_for_engine(scene, "bullet");
    return std::make_unique<BulletWorld>(scene, iterations);
}

}  // namespace

extern const EngineRow bullet_engine;
const EngineRow bullet_engine{"bullet", "btContactSolverInfo::m_numIterations", "Bullet 3.24 (double)",
                              make_bullet_world};

}  // namespace impulse::bench
