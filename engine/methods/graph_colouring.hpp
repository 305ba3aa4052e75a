#pragma once
// A solve order by graph colouring (Box3D, Catto 2026: constraint_graph.c), soft step's `soft_step.order = colours`.
//
// A sweep of Gauss-Seidel visits the contacts one after another, each on the velocities the ones before it left, so
// the order is part of the answer after a sweep or two (soft step makes one per stage). Detection's order runs pair by
// pair through the broad phase's list, in a pyramid row by row from one side to the other: each sweep carries its
// corrections the same way across the scene, and a tall pile leans the way its sweeps run (the large pyramid's top
// drifts 9 cm in its first 5 s at N = 4 in detection's order, 4.8 cm over 10 s in colours; docs/bench.md).
//
// The colouring, Box3D's rules: the pairs are taken in detection's order, and a pair of two moving bodies gets the
// lowest of the first 20 colours that neither body has yet; a pair of a moving body with a static one (the ground, a
// body of infinite mass and inertia) the highest of colours 1 to 22 its moving body has not, so the ground contacts
// come last in a sweep (Box3D: "higher priority": the last visit of a sweep is the one it ends on). A pair for which
// no colour is free goes to the overflow, visited first. Within a colour no two pairs share a moving body, so their
// visits do not depend on each other: a sweep is colour after colour, each colour a step of Jacobi over disjoint
// pairs, and no direction through the scene is favoured. A pair's points stay together, in detection's order, as
// Box3D solves a manifold's points together. Box3D keeps a pair's colour while it touches; this colours every frame
// afresh, which gives the same colours while the pairs and their order are the same.

#include "methods/contact_rows.hpp"

#include <cstdint>
#include <memory_resource>
#include <span>

namespace impulse {

// The colour of each pair of a frame's rows, given as each row's bodies (ContactRow::body, detection's order), as
// colour_slots sorts them: -1 for the overflow, else 0 to 22. `bodies` are the solver's bodies the rows index (a body
// with zero inverse mass and inverse inertia is static). In `scratch` (FrameContext::scratch).
std::pmr::vector<int> pair_colours(std::span<const std::array<int, 2>> pairs, std::span<const SolverBody> bodies,
                                   std::pmr::memory_resource* scratch);

// Where each row goes in the colour order: slot[r] is the place of row r (given by its bodies, as above) among the
// visits, colour by colour (the overflow first), detection's order within a colour. A method builds its rows in
// these slots, so nothing is copied to put them in order.
std::pmr::vector<std::uint32_t> colour_slots(std::span<const std::array<int, 2>> pairs,
                                             std::span<const SolverBody> bodies, std::pmr::memory_resource* scratch);

// The same from the rows' colours (pair_colours).
std::pmr::vector<std::uint32_t> slots_of_colours(std::span<const int> colours, std::pmr::memory_resource* scratch);

}  // namespace impulse
