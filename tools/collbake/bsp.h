/* Quake III BSP (IBSP 46) reader for collbake (bsp.c). */
#ifndef COLLBAKE_BSP_H
#define COLLBAKE_BSP_H

#include <stddef.h>
#include <stdint.h>

typedef void (*bsp_tri_fn)(void *user, const double tri[9]);

typedef struct {
    unsigned surfaces;   /* surfaces looked at (the world model's, or all) */
    unsigned planar, soups, patches; /* solid surfaces taken, by type */
    unsigned nonsolid;   /* skipped: shader without CONTENTS_SOLID, or SURF_NONSOLID */
    unsigned other;      /* skipped: flares and unknown types (no geometry) */
    unsigned triangles;  /* triangles produced (patches tessellated) */
} bsp_stats_t;

/** 1 when d starts with the IBSP magic. */
int bsp_is_bsp(const unsigned char *d, size_t n);

/** Reads the solid surfaces of the world model (all models when all_models), converting
 *  Quake's Z-up units to Y-up metres (x, z, -y) * unit, and calls fn per triangle.
 *  Returns NULL on success, else an error message. */
const char *bsp_read(const unsigned char *d, size_t n, double unit, int all_models, bsp_tri_fn fn, void *user,
                     bsp_stats_t *st);

#endif
