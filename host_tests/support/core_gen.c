/** @file core_gen.c @brief Test-only generators for the collision-core suites. */
#include "core_gen.h"
#include <math.h>

void core_rng_seed(core_rng_t *r, uint64_t seed) { r->s = seed * 0x9E3779B97F4A7C15ull + 1u; }

uint32_t core_rng_u32(core_rng_t *r)
{
    /* splitmix64 */
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (uint32_t)((z ^ (z >> 31)) >> 32);
}

double core_rng_range(core_rng_t *r, double lo, double hi)
{
    return lo + (hi - lo) * ((double)core_rng_u32(r) / 4294967296.0);
}

uint32_t core_grid_level(float *verts, uint32_t *nverts, uint32_t *indices, uint32_t nx, uint32_t nz,
                         float cell, float ox, float oy, float oz)
{
    uint32_t nv = 0, nt = 0;
    for (uint32_t z = 0; z <= nz; z++)
        for (uint32_t x = 0; x <= nx; x++) {
            verts[3 * nv + 0] = ox + (float)x * cell;
            verts[3 * nv + 1] = oy + 0.5f * sinf((float)x * 0.37f) * cosf((float)z * 0.23f);
            verts[3 * nv + 2] = oz + (float)z * cell;
            nv++;
        }
    for (uint32_t z = 0; z < nz; z++)
        for (uint32_t x = 0; x < nx; x++) {
            uint32_t a = z * (nx + 1) + x, b = a + 1, c = a + (nx + 1), d = c + 1;
            indices[3 * nt + 0] = a; indices[3 * nt + 1] = c; indices[3 * nt + 2] = b; nt++;
            indices[3 * nt + 0] = b; indices[3 * nt + 1] = c; indices[3 * nt + 2] = d; nt++;
        }
    *nverts = nv;
    return nt;
}
