/**
 * @file coll/scene.h
 * @brief Fixed-capacity collision scene of mesh instances and convex collider bodies,
 *        with exact raycasts and capsule sweeps. No allocation anywhere.
 */
#ifndef COLL_SCENE_H
#define COLL_SCENE_H

#include "coll/common.h"
#include "coll/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifndef COLL_SCENE_MAX_MESHES
#define COLL_SCENE_MAX_MESHES 64 ///< mesh instances per scene
#endif
#ifndef COLL_SCENE_MAX_BODIES
#define COLL_SCENE_MAX_BODIES 64 ///< collider bodies per scene
#endif

/** A placed mesh. Caller-owned; the game may change xf every frame (moving platforms). */
typedef struct coll_mesh_instance_s {
    const coll_mesh_t *mesh;  ///< shared, immutable mesh data
    coll_transform_t xf;      ///< world placement (translation, rotation, non-uniform scale)
    uint8_t write_mask;       ///< layers this collider is on; seen when write_mask & read_mask
    uint16_t id;              ///< game's id, reported in hits
    uint8_t flags;            ///< COLL_INSTANCE_* (0: an ordinary, solid mesh)
} coll_mesh_instance_t;

/**
 * coll_mesh_instance_t.flags. COLL_INSTANCE_ONE_WAY: a one-way platform. Only its faces that
 * look up along the instance's own up (local +Y, rotated) collide, and only with a query that
 * starts on their front side: a capsule whose axis ends are both above the face's plane
 * (within 5 % of the radius of touching it), a ray whose origin is above it and that points
 * down into it. A body jumps up through it from below or from the side, lands and stands on
 * it, and may drop through on request (char_body_drop_through).
 */
enum { COLL_INSTANCE_ONE_WAY = 1u << 0 };

/** Convex collider body shapes. */
typedef enum {
    COLL_SHAPE_SPHERE = 0,   ///< half_extents.x = radius
    COLL_SHAPE_BOX,          ///< half_extents = half sizes along local X, Y, Z
    COLL_SHAPE_CAPSULE,      ///< x = radius, y = half height of the inner segment along local Y
    COLL_SHAPE_CYLINDER,     ///< x = radius, y = half height along local Y
} coll_shape_t;

/** A convex collider body. Caller-owned; xf may change every frame. xf.scale is ignored. */
typedef struct coll_body_s {
    coll_shape_t shape;
    fm_vec3_t half_extents;
    coll_transform_t xf;
    uint8_t write_mask;
    uint16_t id;
} coll_body_t;

/**
 * Optional counters of the work the queries did: what a fixed buffer could not hold and
 * went a slower, still exact way, for tuning a level (grid cell) and the capacities. The
 * caller owns it and attaches it to a scene (coll_scene_set_stats); the queries only add to
 * it, so it may be shared by several scenes and is reset by the caller (zero it).
 */
typedef struct coll_query_stats_s {
    uint32_t queries;          ///< coll_raycast / coll_capsule_sweep / coll_capsule_overlaps calls on the scene
    uint32_t dedup_overflows;  ///< scene queries whose per-query dedup table filled up (triangles re-tested or looked up in the cells)
    uint32_t gathers;          ///< character steps that gathered their candidate triangles (char_body_move_and_slide_in)
    uint32_t gather_overflows; ///< gathers that found more than their capacity: every query of that step went to the scene
    uint32_t gather_queries;   ///< queries of a step answered from its gathered triangles
    uint32_t gather_misses;    ///< queries of a step that reached outside its gathered box and ran on the scene
} coll_query_stats_t;

/** Registry of caller-owned colliders. Capacity is fixed at compile time. */
typedef struct coll_scene_s {
    coll_mesh_instance_t *meshes[COLL_SCENE_MAX_MESHES];
    coll_body_t *bodies[COLL_SCENE_MAX_BODIES];
    uint16_t mesh_count;
    uint16_t body_count;
    /** Counters the queries add to, or NULL (none): coll_scene_set_stats(). */
    coll_query_stats_t *stats;
} coll_scene_t;

void coll_scene_init(coll_scene_t *scene);
/** COLL_ERR_FULL when full, COLL_ERR_INVALID_ARG for NULL / no mesh / bad transform;
 *  adding the same instance twice is COLL_ERR_INVALID_ARG. Nothing changes on error. */
coll_err_t coll_scene_add_mesh(coll_scene_t *scene, coll_mesh_instance_t *inst);
coll_err_t coll_scene_remove_mesh(coll_scene_t *scene, coll_mesh_instance_t *inst);
coll_err_t coll_scene_add_body(coll_scene_t *scene, coll_body_t *body);
coll_err_t coll_scene_remove_body(coll_scene_t *scene, coll_body_t *body);

/** Attaches counters (or NULL: none, the default after coll_scene_init) that every query on
 *  this scene adds to, including the character body's. */
void coll_scene_set_stats(coll_scene_t *scene, coll_query_stats_t *stats);

/** The scene char_body_move_and_slide() uses. */
void coll_scene_set_current(coll_scene_t *scene);
coll_scene_t *coll_scene_current(void);

/** Raycast result. */
typedef struct {
    fm_vec3_t point;      ///< world hit point
    fm_vec3_t normal;     ///< unit, facing the ray origin
    float distance;       ///< along the ray, meters
    uint16_t id;          ///< collider's id
    uint8_t type;         ///< COLL_TYPE_MESH or COLL_TYPE_BODY
    int32_t triangle;     ///< triangle index in the mesh; -1 for bodies
    const coll_mesh_instance_t *instance; ///< hit mesh instance, or NULL
    const coll_body_t *body;              ///< hit collider body, or NULL
} coll_ray_hit_t;

/** Capsule sweep result. */
typedef struct {
    fm_vec3_t point;      ///< world contact point at time of impact
    fm_vec3_t normal;     ///< unit, pointing from the collider towards the capsule
    float t;              ///< fraction of the displacement travelled, [0,1]
    float depth;          ///< penetration depth when overlapping at t = 0, else 0
    uint16_t id;
    uint8_t type;
    int32_t triangle;
    const coll_mesh_instance_t *instance;
    const coll_body_t *body;
} coll_sweep_hit_t;

/**
 * Nearest hit of a ray, exactly. Triangles are two-sided. Returns false for no hit or an
 * invalid query (non-finite values, non-positive max_dist).
 */
bool coll_raycast(const coll_scene_t *scene, fm_vec3_t origin, fm_vec3_t dir_unit, float max_dist,
                  uint8_t read_mask, uint8_t coll_types, coll_ray_hit_t *hit);

/**
 * Earliest time of impact of a capsule (segment center +- axis * inner_half_height, radius)
 * moving by displacement. An initial overlap is reported with t = 0, the penetration depth
 * and the direction that pushes the capsule out; among several overlaps the deepest wins.
 */
bool coll_capsule_sweep(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis_up_unit,
                        float radius, float inner_half_height, fm_vec3_t displacement,
                        uint8_t read_mask, uint8_t coll_types, coll_sweep_hit_t *hit);

/** One overlapping feature, from coll_capsule_overlaps(). */
typedef struct {
    fm_vec3_t normal;     ///< push-out direction (unit), collider towards capsule
    fm_vec3_t point;      ///< closest point on the collider
    float depth;          ///< penetration, > 0
    uint16_t id;
    uint8_t type;
    int32_t triangle;
    const coll_mesh_instance_t *instance;
    const coll_body_t *body;
} coll_contact_t;

/**
 * Every collider feature the capsule overlaps (for recovery from penetration), deepest
 * first, at most max_out of them; returns how many there were in total (which may exceed
 * max_out: the deepest max_out are kept).
 */
uint32_t coll_capsule_overlaps(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis_up_unit,
                               float radius, float inner_half_height, uint8_t read_mask,
                               uint8_t coll_types, coll_contact_t *out, uint32_t max_out);

#ifdef __cplusplus
}
#endif
#endif
