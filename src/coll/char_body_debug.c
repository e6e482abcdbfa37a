/**
 * @file char_body_debug.c
 * @brief Debug wireframe of a character body through a line callback (the seed's colours).
 */
#include "char_body_internal.h"

#define CB_DEBUG_SEGS 12 /* segments per circle */

/** Two unit vectors spanning the plane across up. */
static void basis(fm_vec3_t up, fm_vec3_t *e1, fm_vec3_t *e2)
{
    fm_vec3_t a = fabsf(up.x) < 0.9f ? v3(1.0f, 0.0f, 0.0f) : v3(0.0f, 0.0f, 1.0f);
    *e1 = v3_norm(v3_cross(up, a));
    *e2 = v3_cross(up, *e1);
}

static void line(const coll_debug_draw_t *dd, fm_vec3_t a, fm_vec3_t b, uint32_t rgba)
{
    dd->line(dd->user, a, b, rgba);
}

/** Capsule: rings at both ends of the inner segment, four side lines, two half-arcs per cap. */
static void capsule(const coll_debug_draw_t *dd, fm_vec3_t center, fm_vec3_t up, float r, float ihh, uint32_t rgba)
{
    fm_vec3_t e1, e2;
    basis(up, &e1, &e2);
    fm_vec3_t top = v3_madd(center, up, ihh), bot = v3_madd(center, up, -ihh);
    for (int i = 0; i < CB_DEBUG_SEGS; i++) {
        float a0 = 2.0f * FM_PI * (float)i / CB_DEBUG_SEGS, a1 = 2.0f * FM_PI * (float)(i + 1) / CB_DEBUG_SEGS;
        fm_vec3_t d0 = v3_add(v3_scale(e1, r * cosf(a0)), v3_scale(e2, r * sinf(a0)));
        fm_vec3_t d1 = v3_add(v3_scale(e1, r * cosf(a1)), v3_scale(e2, r * sinf(a1)));
        line(dd, v3_add(top, d0), v3_add(top, d1), rgba);
        line(dd, v3_add(bot, d0), v3_add(bot, d1), rgba);
    }
    const fm_vec3_t side[2] = {e1, e2};
    for (int k = 0; k < 2; k++) {
        fm_vec3_t e = side[k];
        line(dd, v3_madd(top, e, r), v3_madd(bot, e, r), rgba);
        line(dd, v3_madd(top, e, -r), v3_madd(bot, e, -r), rgba);
        /* half circles over the caps, in the plane of e and up */
        for (int i = 0; i < CB_DEBUG_SEGS / 2; i++) {
            float a0 = FM_PI * (float)i / (CB_DEBUG_SEGS / 2), a1 = FM_PI * (float)(i + 1) / (CB_DEBUG_SEGS / 2);
            fm_vec3_t p0 = v3_add(v3_scale(e, r * cosf(a0)), v3_scale(up, r * sinf(a0)));
            fm_vec3_t p1 = v3_add(v3_scale(e, r * cosf(a1)), v3_scale(up, r * sinf(a1)));
            line(dd, v3_add(top, p0), v3_add(top, p1), rgba);
            fm_vec3_t q0 = v3_madd(p0, up, -2.0f * r * sinf(a0)), q1 = v3_madd(p1, up, -2.0f * r * sinf(a1));
            line(dd, v3_add(bot, q0), v3_add(bot, q1), rgba);
        }
    }
}

void char_body_debug_draw(const char_body_t *body, const coll_debug_draw_t *dd)
{
    if (!body || !dd || !dd->line) return;
    const char_body_settings_t *s = &body->settings;
    fm_vec3_t up = s->up;
    fm_vec3_t pos = owner_position(body);
    fm_vec3_t center = v3_add(pos, s->center_offset);
    float hh = 0.5f * s->height;
    fm_vec3_t foot = v3_madd(center, up, -hh);
    float sweep_ihh = body->inner_half_height - 0.5f * s->step_height;
    if (sweep_ihh < 0.0f) sweep_ihh = 0.0f;

    uint32_t state = CHAR_BODY_COLOR_AIRBORNE;
    if (body->flags & CB_FLAG_GROUNDED)
        state = (body->flags & CB_FLAG_STEEP) ? CHAR_BODY_COLOR_STEEP : CHAR_BODY_COLOR_FLOOR;

    capsule(dd, center, up, s->radius, body->inner_half_height, CHAR_BODY_COLOR_FULL);
    capsule(dd, v3_madd(center, up, 0.5f * s->step_height), up, s->radius, sweep_ihh, state);

    /* Step zone: a cross at the bottom of the sweep capsule, and its height from the foot. */
    fm_vec3_t e1, e2;
    basis(up, &e1, &e2);
    fm_vec3_t step_top = v3_madd(foot, up, s->step_height);
    line(dd, v3_madd(step_top, e1, -s->radius), v3_madd(step_top, e1, s->radius), CHAR_BODY_COLOR_STEP_ZONE);
    line(dd, v3_madd(step_top, e2, -s->radius), v3_madd(step_top, e2, s->radius), CHAR_BODY_COLOR_STEP_ZONE);
    line(dd, foot, step_top, CHAR_BODY_COLOR_STEP_ZONE);

    /* Floor probe: from the capsule centre down to the snap reach. */
    line(dd, center, v3_madd(foot, up, -s->floor_snap_distance), CHAR_BODY_COLOR_PROBE);

    if (body->flags & CB_FLAG_GROUNDED)
        line(dd, foot, v3_madd(foot, body->floor_normal, s->radius), CHAR_BODY_COLOR_NORMAL);
}
