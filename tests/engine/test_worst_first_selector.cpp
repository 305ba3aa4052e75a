// The scalable worst-first search against the book's full scan: the tournament tree alone against a
// brute-force maximum, both selectors on random values, the body index against a loop, and whole runs
// compared pick by pick.

#include "formats/settings_json.hpp"
#include "record/trace_recorder.hpp"
#include "methods/worst_first_selector.hpp"
#include "support/shipped.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace impulse;

namespace {

// The scan's rule, written out: the largest value, the lowest index on a tie, NaN never.
std::optional<int> brute_force_top(const std::vector<double>& value, const std::vector<char>& present) {
    std::optional<int> best;
    for (int i = 0; i < static_cast<int>(value.size()); ++i) {
        const auto u = static_cast<std::size_t>(i);
        if (!present[u] || std::isnan(value[u])) continue;
        if (!best || value[u] > value[static_cast<std::size_t>(*best)]) best = i;
    }
    return best;
}

// What a phase chose, iteration by iteration, and nothing else: cheap enough for large scenes.
struct PickLog : Recorder {
    std::vector<std::tuple<int, int, int, double>> picks;  // frame, phase, contact, value
    int frame = 0;
    void begin_frame(int f, std::span<const RigidBody>, std::span<const MassProperties>) override { frame = f; }
    bool keeps_frame() const override { return true; }
    void position_visit(const PositionVisit& v) override {
        picks.emplace_back(frame, 0, v.contact, v.resolution->penetration);
    }
    void velocity_visit(const VelocityVisit& v) override {
        picks.emplace_back(frame, 1, v.contact, v.resolution->desired_terms.desired_delta_velocity);
    }
};

struct Run {
    PickLog log;
    std::vector<RigidBody> bodies;
};

Run run(const std::string& name, int frames, WorstFirstSearch search, const std::vector<std::string>& settings) {
    Scene scene = test::shipped(name);
    for (const std::string& s : settings) formats::apply_setting(scene, s, "--set");
    scene.settings.worst_first_search = search;
    Run r;
    World world(scene);
    for (int frame = 0; frame < frames; ++frame) world.step(r.log);
    r.bodies = world.bodies();
    return r;
}

}  // namespace

TEST_CASE("the contact tournament always tops with the largest value and the lowest index on a tie") {
    // Values drawn from a few levels so ties are common, now and then a NaN (the scan never picks one) or an
    // infinity; trees of one leaf, of a count that is not a power of two, and of many leaves. (No -infinity:
    // it ranks with NaN, and neither can pass an epsilon.)
    std::mt19937 random(7);
    const auto draw = [&random] {
        const int level = static_cast<int>(random() % 10);
        if (level == 8) return std::numeric_limits<double>::quiet_NaN();
        if (level == 9) return std::numeric_limits<double>::infinity();
        return 0.25 * level - 0.5;
    };
    for (const int n : {1, 3, 40}) {
        CAPTURE(n);
        std::vector<double> value(static_cast<std::size_t>(n), 0.0);
        std::vector<char> present(static_cast<std::size_t>(n), 0);
        ContactTournament tree;
        tree.clear(static_cast<std::size_t>(n));
        CHECK(!tree.top());
        for (int step = 0; step < 5000; ++step) {
            const int i = static_cast<int>(random() % static_cast<unsigned>(n));
            const auto u = static_cast<std::size_t>(i);
            const int action = static_cast<int>(random() % 3);
            if (action == 0 && !present[u]) {
                value[u] = draw();
                tree.insert(i, value[u]);
                present[u] = 1;
            } else if (action == 1) {
                value[u] = draw();
                tree.change(i, value[u]);  // no effect on an absent contact, as in the brute force
            } else {
                tree.remove(i);
                present[u] = 0;
            }
            if (step % 500 == 0) tree.fill(value, present);  // the same contacts in play, all placed at once
            const std::optional<int> expected = brute_force_top(value, present);
            const std::optional<int> top = tree.top();
            // A tournament holding only NaNs may still have a top; the selector then compares it with the
            // epsilon and finds nothing, as the scan does.
            if (top) REQUIRE(tree.top_value() == tree.value(*top));
            if (expected)
                REQUIRE(top == expected);
            else if (top)
                REQUIRE(std::isnan(value[static_cast<std::size_t>(*top)]));
            for (int k = 0; k < n; ++k) REQUIRE(tree.contains(k) == (present[static_cast<std::size_t>(k)] != 0));
        }
    }
}

TEST_CASE("a tournament changed several contacts at once ranks every contact as one changed one by one") {
    // Batches of ascending contacts (neighbours, far apart, some not in play) get new values; the batch
    // tree and a tree changed one contact at a time must then give up their contacts in the same order
    // (largest first, lowest index on a tie), which checks every match, not only the final one.
    std::mt19937 random(17);
    constexpr int n = 100;
    ContactTournament batch, single;
    std::vector<double> start(n);
    std::vector<char> present(n);
    for (int i = 0; i < n; ++i) {
        start[static_cast<std::size_t>(i)] = 0.1 * static_cast<double>(random() % 5);
        present[static_cast<std::size_t>(i)] = random() % 8 != 0;
    }
    batch.fill(start, present);
    single.fill(start, present);
    const auto ranking = [](ContactTournament tree) {
        std::vector<int> order;
        while (const std::optional<int> top = tree.top()) {
            order.push_back(*top);
            tree.remove(*top);
        }
        CHECK(order.size() <= static_cast<std::size_t>(n));
        return order;
    };
    for (int round = 0; round < 400; ++round) {
        std::vector<int> contacts;
        const int first = static_cast<int>(random() % n);
        for (int i = first; i < n; i += 1 + static_cast<int>(random() % (round % 2 == 0 ? 3 : 40)))
            if (contacts.size() < 8) contacts.push_back(i);
        std::vector<double> values;
        for (std::size_t k = 0; k < contacts.size(); ++k) values.push_back(0.1 * static_cast<double>(random() % 5));
        batch.change(contacts, values);
        for (std::size_t k = 0; k < contacts.size(); ++k) single.change(contacts[k], values[k]);
        REQUIRE(ranking(batch) == ranking(single));
    }
}

TEST_CASE("both worst-first searches choose the same contact after any sequence of random updates") {
    // 300 contacts on 60 bodies (some with the world, some between two bodies), penetrations from a few
    // levels so ties are common. Each round: both selectors pick, the picked contact's bodies "move", every
    // contact sharing them gets a new random value, both are told, and now and then a contact is set aside
    // (relaxation) or every contact is put back (a new pass).
    std::mt19937 random(31);
    const int bodies = 60, count = 300;
    std::vector<PreparedContact> contacts(count);
    for (PreparedContact& c : contacts) {
        const int a = static_cast<int>(random() % bodies);
        const int b = random() % 3 == 0 ? static_cast<int>(random() % bodies) : world_body;
        c.bodies = {a, b == a ? world_body : b};
        c.penetration = 0.01 * static_cast<double>(random() % 7);
    }
    const auto penetration_of = [](const PreparedContact& c) { return c.penetration; };
    std::vector<char> eligible(count);
    for (char& e : eligible) e = random() % 10 != 0;  // a few inert contacts never chosen
    WorstFirstSelector scan(WorstFirstSearch::full_scan, contacts, bodies, penetration_of, eligible);
    WorstFirstSelector queue(WorstFirstSearch::priority_queue, contacts, bodies, penetration_of, eligible);
    const double epsilon = 0.015;
    int picks = 0;
    for (int round = 0; round < 3000; ++round) {
        const std::optional<int> a = scan.worst(epsilon), b = queue.worst(epsilon);
        REQUIRE(a == b);
        if (!a || round % 97 == 0) {
            scan.restart();
            queue.restart();
            continue;
        }
        ++picks;
        if (round % 5 == 0) {
            scan.set_aside(*a);
            queue.set_aside(*a);
        }
        const std::array<int, 2> moved = contacts[static_cast<std::size_t>(*a)].bodies;
        const std::vector<int> sharing(queue.sharing(moved).begin(), queue.sharing(moved).end());
        for (const int i : sharing)
            contacts[static_cast<std::size_t>(i)].penetration = 0.01 * static_cast<double>(random() % 7);
        scan.values_changed(scan.sharing(moved));
        queue.values_changed(sharing);
    }
    CHECK(picks > 2000);
}

TEST_CASE("the contacts sharing a body come once each and in index order") {
    const auto contact_between = [](int a, int b) {
        PreparedContact c{};
        c.bodies = {a, b};
        return c;
    };
    // Contact 3 touches both bodies 0 and 1; contact 1 touches neither.
    const std::vector<PreparedContact> contacts{contact_between(0, world_body), contact_between(2, world_body),
                                                contact_between(1, world_body), contact_between(0, 1),
                                                contact_between(1, 2)};
    const ContactsByBody index(contacts, 3);
    std::vector<int> out;
    index.sharing({0, 1}, out);
    CHECK(out == std::vector<int>{0, 2, 3, 4});
    index.sharing({2, world_body}, out);
    CHECK(out == std::vector<int>{1, 4});
    index.sharing({1, 1}, out);
    CHECK(out == std::vector<int>{2, 3, 4});
}

TEST_CASE(
    "priority-queue worst-first picks the same contacts as the full scan pick by pick and ends in the same state") {
    struct Case {
        std::string scene;
        int frames;
        std::vector<std::string> settings;
    };
    // Every position method that chooses worst-first, on scenes where many contacts share bodies.
    const std::vector<Case> cases{
        {"stack_10", 40, {}},
        {"pyramid_10", 20, {"position_method=linear_projection"}},
        {"brick_wall", 10, {"position_method=relaxation"}},
        {"box_tipping", 60, {"position_method=velocity_based"}},
        {"pile_200", 60, {"preset=chapter"}},
    };
    for (const Case& c : cases) {
        CAPTURE(c.scene);
        const Run scan = run(c.scene, c.frames, WorstFirstSearch::full_scan, c.settings);
        const Run heap = run(c.scene, c.frames, WorstFirstSearch::priority_queue, c.settings);
        CHECK(scan.log.picks.size() > 100);
        REQUIRE(heap.log.picks.size() == scan.log.picks.size());
        // The first pick where they part, if any (one check, not one per pick: the lists run to 50,000).
        const auto parted = std::mismatch(scan.log.picks.begin(), scan.log.picks.end(), heap.log.picks.begin()).first;
        CAPTURE(parted - scan.log.picks.begin());
        CHECK(parted == scan.log.picks.end());
        REQUIRE(heap.bodies.size() == scan.bodies.size());
        for (std::size_t b = 0; b < scan.bodies.size(); ++b) {
            CHECK(heap.bodies[b].position == scan.bodies[b].position);
            CHECK(heap.bodies[b].orientation.coeffs() == scan.bodies[b].orientation.coeffs());
            CHECK(heap.bodies[b].velocity == scan.bodies[b].velocity);
        }
    }
}

TEST_CASE("priority-queue worst-first records the same trace as the full scan, updates included") {
    const auto traced = [](WorstFirstSearch search) {
        Trace trace;
        trace.scene = test::shipped("stack_3");
        trace.scene.settings.worst_first_search = search;
        trace.recording.last_frame = 9;
        World world(trace.scene);
        TraceRecorder recorder(trace);
        for (int frame = 0; frame < 10; ++frame) world.step(recorder);
        return trace.frames;
    };
    const std::vector<FrameRecord> scan = traced(WorstFirstSearch::full_scan);
    REQUIRE(scan.size() == 10);
    CHECK(traced(WorstFirstSearch::priority_queue) == scan);
}
