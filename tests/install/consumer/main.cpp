// Reads a case with the installed formats library, resolves it with the installed engine and prints the first
// body's velocity after. Exit 0 when the program ran; the test compares what it printed.

#include "formats/scene_file.hpp"
#include "resolver/resolver.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: consumer CASE.json\n");
        return 2;
    }
    std::ifstream in(argv[1]);
    std::stringstream text;
    text << in.rdbuf();
    impulse::Scene scene = impulse::formats::read_scene_text(text.str(), std::string("book"));
    std::vector<impulse::RigidBody> bodies = scene.bodies;
    impulse::resolve_contacts(bodies, scene.contacts, scene.settings);
    const auto& v = bodies[0].velocity;
    std::printf("velocity after: %.6f %.6f %.6f\n", v.x(), v.y(), v.z());
    return 0;
}
