#pragma once
// Particle swarm optimisation (Kennedy & Eberhart 1995) with the constriction coefficients of
// Clerc & Kennedy 2002 (w = 0.7298, c1 = c2 = 1.49618), global-best topology. Particles start
// uniformly within the search radius around the start (particle 0 exactly at the start);
// velocities are clamped to the radius.
#include "search/SearchProblem.h"

namespace fm {

struct ParticleSwarmSettings {
    int particles = 16;
    double inertia = 0.7298;
    double cognitive = 1.49618;
    double social = 1.49618;
};

void runParticleSwarm(SearchProblem& problem, const ParticleSwarmSettings& settings = {});

}  // namespace fm
