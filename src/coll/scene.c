/**
 * @file scene.c
 * @brief Fixed-capacity registry of caller-owned mesh instances and collider bodies.
 *        The queries live in query.c.
 */
#include "vec3.h"
#include "coll/scene.h"
#include <math.h>
#include <string.h>

static coll_scene_t *g_current;

void coll_scene_init(coll_scene_t *scene)
{
    if (scene) memset(scene, 0, sizeof *scene);
}

void coll_scene_set_stats(coll_scene_t *scene, coll_query_stats_t *stats)
{
    if (scene) scene->stats = stats;
}

void coll_scene_set_current(coll_scene_t *scene) { g_current = scene; }

coll_scene_t *coll_scene_current(void) { return g_current; }

static bool xf_valid(const coll_transform_t *xf, bool check_scale)
{
    if (!v3_finite(xf->pos)) return false;
    const fm_quat_t *q = &xf->rot;
    if (!isfinite(q->x) || !isfinite(q->y) || !isfinite(q->z) || !isfinite(q->w)) return false;
    if (!(q->x * q->x + q->y * q->y + q->z * q->z + q->w * q->w > 1e-12f)) return false;
    if (check_scale) {
        if (!v3_finite(xf->scale)) return false;
        if (xf->scale.x == 0.0f || xf->scale.y == 0.0f || xf->scale.z == 0.0f) return false;
    }
    return true;
}

coll_err_t coll_scene_add_mesh(coll_scene_t *scene, coll_mesh_instance_t *inst)
{
    if (!scene || !inst || !inst->mesh || !xf_valid(&inst->xf, true)) return COLL_ERR_INVALID_ARG;
    for (uint16_t i = 0; i < scene->mesh_count; i++)
        if (scene->meshes[i] == inst) return COLL_ERR_INVALID_ARG;
    if (scene->mesh_count >= COLL_SCENE_MAX_MESHES) return COLL_ERR_FULL;
    scene->meshes[scene->mesh_count++] = inst;
    return COLL_OK;
}

coll_err_t coll_scene_remove_mesh(coll_scene_t *scene, coll_mesh_instance_t *inst)
{
    if (!scene || !inst) return COLL_ERR_INVALID_ARG;
    for (uint16_t i = 0; i < scene->mesh_count; i++) {
        if (scene->meshes[i] == inst) {
            /* Keep the order of the others (queries are order-independent, but stable
             * order keeps tie-breaking predictable). */
            memmove(&scene->meshes[i], &scene->meshes[i + 1],
                    (size_t)(scene->mesh_count - i - 1u) * sizeof scene->meshes[0]);
            scene->meshes[--scene->mesh_count] = NULL;
            return COLL_OK;
        }
    }
    return COLL_ERR_NOT_FOUND;
}

coll_err_t coll_scene_add_body(coll_scene_t *scene, coll_body_t *body)
{
    if (!scene || !body || !xf_valid(&body->xf, false) || !v3_finite(body->half_extents) ||
        (unsigned)body->shape > (unsigned)COLL_SHAPE_CYLINDER)
        return COLL_ERR_INVALID_ARG;
    for (uint16_t i = 0; i < scene->body_count; i++)
        if (scene->bodies[i] == body) return COLL_ERR_INVALID_ARG;
    if (scene->body_count >= COLL_SCENE_MAX_BODIES) return COLL_ERR_FULL;
    scene->bodies[scene->body_count++] = body;
    return COLL_OK;
}

coll_err_t coll_scene_remove_body(coll_scene_t *scene, coll_body_t *body)
{
    if (!scene || !body) return COLL_ERR_INVALID_ARG;
    for (uint16_t i = 0; i < scene->body_count; i++) {
        if (scene->bodies[i] == body) {
            memmove(&scene->bodies[i], &scene->bodies[i + 1],
                    (size_t)(scene->body_count - i - 1u) * sizeof scene->bodies[0]);
            scene->bodies[--scene->body_count] = NULL;
            return COLL_OK;
        }
    }
    return COLL_ERR_NOT_FOUND;
}
