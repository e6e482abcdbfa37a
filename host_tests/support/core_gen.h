/**
 * @file core_gen.h
 * @brief Test-only level generators and a deterministic RNG for the collision-core suites
 *        (test_mesh, test_mesh_load, test_scene_query).
 */
#ifndef CORE_GEN_H
#define CORE_GEN_H
#include <stdint.h>

typedef struct { uint64_t s; } core_rng_t;

void core_rng_seed(core_rng_t *r, uint64_t seed);
uint32_t core_rng_u32(core_rng_t *r);
/** Uniform in [lo, hi). */
double core_rng_range(core_rng_t *r, double lo, double hi);

/**
 * Welded grid-like level: an nx x nz height-field of quads (2 triangles each) of edge
 * `cell` meters with gentle bumps, plus nothing else. Writes (nx+1)*(nz+1) vertices and
 * 2*nx*nz triangles into the caller's arrays; returns the triangle count.
 */
uint32_t core_grid_level(float *verts, uint32_t *nverts, uint32_t *indices, uint32_t nx, uint32_t nz,
                         float cell, float ox, float oy, float oz);
#endif
