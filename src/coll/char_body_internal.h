/**
 * @file char_body_internal.h
 * @brief Private pieces of the character body shared by its source files: the per-step
 *        context and the phase functions of one step (vectors: vec3.h).
 */
#ifndef COLL_CHAR_BODY_INTERNAL_H
#define COLL_CHAR_BODY_INTERNAL_H

#include "coll_libm.h"
#include "coll/char_body.h"
#include "gather.h"
#include "vec3.h"

/** Private bits of char_body_t.flags. */
enum {
    CB_FLAG_GROUNDED = 1u << 0, ///< standing on a floor (walkable or steep)
    CB_FLAG_STEEP    = 1u << 1, ///< the floor is steeper than floor_max_angle
    CB_FLAG_CARRY    = 1u << 2, ///< floor_local_point / floor_world_point are valid
    CB_FLAG_CARRIED  = 1u << 3, ///< carry_velocity holds the last step's carry (same floor)
};

/* Tolerances. Each says why it exists. Lengths are in metres here: the body uses them times
 * settings.units_per_meter (cb_ctx_t.unit, cb_len_tol), so a game in centimetres gets the
 * same tolerances, in centimetres. docs/ARCHITECTURE.md tables them all. */
/** Gap kept between the sweep capsule and what it hit: the next sweep starts clear, not
 *  touching. At most 1 % of the radius, so small capsules rest where they should. */
#define CB_SKIN 0.001f
/** Longest simulated step: larger dt (hitches, 10 s pauses) is clamped so nothing tunnels or explodes. */
#define CB_MAX_DT 0.1f
/** Speed limit of the resolved velocity, m/s: keeps sweeps short and numbers finite. */
#define CB_MAX_SPEED 200.0f
/** Largest gravity accepted, m/s^2 (about 100 g). */
#define CB_MAX_GRAVITY 1000.0f
/** Largest radius, snap distance (and a quarter of the largest height) accepted, m. */
#define CB_MAX_LENGTH 1000.0f
/** Smallest radius accepted, m. */
#define CB_MIN_RADIUS 0.001f
/** Floor this close below the foot counts as touching even when not snapping (landing). */
#define CB_CONTACT_EPS 0.002f
/** Overlaps shallower than this are touching contacts, not penetrations to recover from. */
#define CB_MIN_DEPTH 0.0001f
/** Height margin, m: a contact this far above the step zone still counts as in it (walls
 *  while walking), a steep plane this far above its resting place is still stood on. */
#define CB_MARGIN 0.01f
/** Height tolerance of the stair step and the probe's lift, m: rises and treads compared
 *  within it, lifts shorter than it are not "no room". */
#define CB_STEP_EPS 0.001f
/* n.up at or above which a face counts as level: 1 less a few float ulps, the rounding of a
 * unit normal computed from a level triangle's vertices */
#define CB_LEVEL_NU 0.9999997f
/* contact normal . face normal at or above which a sweep's contact is on the face itself, not
 * on its edge or vertex: a face contact's normal is the face's to float rounding (a few ulps);
 * an edge's or a vertex's is off it by the angle at which the ball's centre lies past the edge:
 * 0.08 degrees at this bound, the centre r / 700 past it (held_on_edge_alone) */
#define CB_FACE_ON 0.999999f
/** Walking, a slide that ends this far behind its start along the input went backwards
 *  (skin corrections in a corner): it is redone without the backward part, m. Above float
 *  noise at positions of a few hundred metres. */
#define CB_BACK_TOL 1e-5f
/** Motion shorter than this is none (a sweep is skipped, a direction not taken), m. */
#define CB_TINY 1e-6f
/** Most slide planes remembered in one step (max_slides is at most 8). */
#define CB_MAX_PLANES 8
/** With a gather cache (char_body.c, gather_step): a refill keeps the step's box, swept
 *  this many steps ahead at the step's velocity (at most CB_GATHER_CACHE_AHEAD m), grown by
 *  CB_GATHER_CACHE_MARGIN m on each side (perf14: measured on the sample walk, the crowd,
 *  the Jolt scene and the real maps). */
#ifndef CB_GATHER_CACHE_STEPS
#define CB_GATHER_CACHE_STEPS 6
#endif
#ifndef CB_GATHER_CACHE_AHEAD
#define CB_GATHER_CACHE_AHEAD 1.0f
#endif
#ifndef CB_GATHER_CACHE_MARGIN
#define CB_GATHER_CACHE_MARGIN 0.1f
#endif
/** Contacts used by the overlap recovery. */
#define CB_MAX_CONTACTS 4


/** The stair step's down sweep, remembered (coll_cb_sweep_down): the sweep capsule at owner
 *  position `pos` going down along -up by `len`, `dist` along it to the first contact `h`
 *  (when `hit`). Moved along up since (coll_cb_down_moved: unswept, the way it came), pos, len
 *  and dist say so. Moving along its axis from a clear start the capsule's first contact
 *  is its bottom ball's: a later down sweep of either from the same place reaching no
 *  farther is answered from it (cb_down_known). */
typedef struct {
    fm_vec3_t pos;
    float len;
    float dist;
    bool valid;
    bool hit;
    coll_sweep_hit_t h;
} cb_down_t;

/** The step's memory of its queries (cb_ctx_t.mem, always present): the stair step's down
 *  sweep and its foot ray (the probe's, when the body stays there); what the last overlap
 *  query on the step's gather learnt, for a sweep from the same place (coll_gather_memo_t:
 *  the recovery's overlap and the slide's first sweep). */
typedef struct {
    cb_down_t down;
    coll_gather_memo_t pairs;
    bool ray_valid;
    bool ray_found;
    fm_vec3_t ray_origin;
    float ray_len;
    coll_ray_hit_t ray_hit;
    /** Set (never cleared) by the floor probe when the crack rule held the ball on edges it
     *  has no room to be lifted onto, over a floor out of reach below, and the body was left
     *  falling towards that floor: coll_cb_unwedge clears it before the probes it reads it
     *  after. Uninitialised otherwise. */
    bool edges_no_room;
    /** Set by the floor probe when the crack rule alone, with no floor it falls straight
     *  onto (none in the foot ray's reach, or one a straight fall cannot reach: soak s59
     *  l264), held the ball on edges it has no room to be lifted onto (the probe failed
     *  there); cleared once per step (char_body_move_and_slide_in). The step's fall-only retry
     *  then slides (and is not kept where that slide stopped dead: soak s44 l175), and
     *  coll_cb_unwedge treats an airborne start as wedged (soak s30 l14). */
    bool crack_no_floor;
    /** Set when coll_cb_recover moved the body (cleared once per step); `push` is then how far
     *  (the step reports its part across up beyond the skin as motion: soak s134 l270). */
    bool pushed;
    fm_vec3_t push;
} cb_mem_t;

/** What one step works with: the scene, the body's cached geometry and the current up. */
typedef struct {
    const coll_scene_t *scene;
    char_body_t *body;
    fm_vec3_t up;
    float radius;
    float half_height;   ///< full capsule half height (height / 2)
    float sweep_ihh;     ///< inner half height of the sweep capsule
    float sweep_lift;    ///< sweep capsule centre above the full capsule centre (step / 2)
    float step;          ///< step height
    float snap;          ///< floor snap distance
    float skin;          ///< contact gap: CB_SKIN, or 1 % of the radius when smaller
    float unit;          ///< settings.units_per_meter: the metre tolerances' scale
    float contact_eps;   ///< CB_CONTACT_EPS in the body's unit
    float min_depth;     ///< CB_MIN_DEPTH in the body's unit
    float tiny;          ///< CB_TINY in the body's unit
    float dt;            ///< this step's (clamped) duration, s
    float max_speed;     ///< CB_MAX_SPEED in the body's unit: no motion across up is faster
    char_body_events_t *ev; ///< events of the main slide and probe; NULL for the carry's slide
    coll_gather_t *gather; ///< the step's candidate triangles (their prep filled by the queries), or NULL
    cb_mem_t *mem;         ///< the step's query memory (never NULL)
} cb_ctx_t;

/** A tolerance given in metres (CB_*), in the body's length unit (the ones used on every
 *  step are in cb_ctx_t already). */
static inline float cb_len_tol(const cb_ctx_t *c, float metres) { return metres * c->unit; }

/** How far a capsule whose bottom ball's centre is `off` across up from an edge it rests on
 *  is pushed off that edge: clear of it by the skin (slide_off_edge; held_on_edge_alone
 *  asks whether there is room for it). */
static inline float cb_off_edge_push(const cb_ctx_t *c, float off) { return c->radius + c->skin - off; }

/* The body's queries: on the step's gather when there is one (it falls back to the scene
 * by itself for a query reaching outside the gathered box), else on the scene. The body's
 * read_mask and coll_types; capsule and ray axes along the body's up. */
static inline bool cb_ray(const cb_ctx_t *c, fm_vec3_t o, fm_vec3_t dir, float max_dist, coll_ray_hit_t *hit)
{
    if (c->gather) return coll_gather_raycast(c->gather, o, dir, max_dist, hit);
    return coll_raycast(c->scene, o, dir, max_dist, c->body->settings.read_mask, c->body->settings.coll_types, hit);
}
static inline bool cb_sweep(const cb_ctx_t *c, fm_vec3_t center, float radius, float ihh, fm_vec3_t disp,
                            coll_sweep_hit_t *hit)
{
    if (c->gather) return coll_gather_capsule_sweep(c->gather, center, c->up, radius, ihh, disp, hit);
    return coll_capsule_sweep(c->scene, center, c->up, radius, ihh, disp, c->body->settings.read_mask,
                              c->body->settings.coll_types, hit);
}
/* cb_sweep for the stair step's sweeps (coll_gather_capsule_sweep_corner): the same answer */
static inline bool cb_sweep_step(const cb_ctx_t *c, fm_vec3_t center, float radius, float ihh, fm_vec3_t disp,
                                 coll_sweep_hit_t *hit)
{
    if (c->gather) return coll_gather_capsule_sweep_corner(c->gather, center, c->up, radius, ihh, disp, hit);
    return coll_capsule_sweep(c->scene, center, c->up, radius, ihh, disp, c->body->settings.read_mask,
                              c->body->settings.coll_types, hit);
}
/* cb_sweep for the slide's sweeps of the sweep capsule: one from where the recovery's
 * overlap query just looked skips what that query found clear (coll_gather_memo_t); the
 * same answer. */
static inline bool cb_sweep_slide(const cb_ctx_t *c, fm_vec3_t center, fm_vec3_t disp, coll_sweep_hit_t *hit)
{
    if (c->gather && coll_gather_memo_for(&c->mem->pairs, c->gather, center, c->up, c->radius, c->sweep_ihh))
        return coll_gather_capsule_sweep_m(c->gather, center, c->up, c->radius, c->sweep_ihh, disp, NULL,
                                           &c->mem->pairs, hit);
    return cb_sweep(c, center, c->radius, c->sweep_ihh, disp, hit);
}
/* cb_sweep for a sweep the caller knows stays above a plane (coll_gather_above_t): on the
 * gather, the triangles lying under it are not tested; the answer is cb_sweep's. */
static inline bool cb_sweep_above(const cb_ctx_t *c, fm_vec3_t center, float radius, float ihh, fm_vec3_t disp,
                                  const coll_gather_above_t *above, coll_sweep_hit_t *hit)
{
    if (c->gather) return coll_gather_capsule_sweep_above(c->gather, center, c->up, radius, ihh, disp, above, hit);
    return coll_capsule_sweep(c->scene, center, c->up, radius, ihh, disp, c->body->settings.read_mask,
                              c->body->settings.coll_types, hit);
}
/* cb_overlaps for the recovery's first look: what it finds clear is remembered for the
 * slide's first sweep from there (cb_sweep_slide). */
static inline uint32_t cb_overlaps_remember(const cb_ctx_t *c, fm_vec3_t center, coll_contact_t *out, uint32_t max_out)
{
    if (c->gather)
        return coll_gather_capsule_overlaps_m(c->gather, center, c->up, c->radius, c->sweep_ihh, out, max_out,
                                              &c->mem->pairs);
    return coll_capsule_overlaps(c->scene, center, c->up, c->radius, c->sweep_ihh, c->body->settings.read_mask,
                                 c->body->settings.coll_types, out, max_out);
}
static inline uint32_t cb_overlaps(const cb_ctx_t *c, fm_vec3_t center, coll_contact_t *out, uint32_t max_out)
{
    if (c->gather) return coll_gather_capsule_overlaps(c->gather, center, c->up, c->radius, c->sweep_ihh, out, max_out);
    return coll_capsule_overlaps(c->scene, center, c->up, c->radius, c->sweep_ihh, c->body->settings.read_mask,
                                 c->body->settings.coll_types, out, max_out);
}

/** Contacts a ball's overlap query keeps (cb_ball_overlaps: the deepest). */
#define CB_BALL_CONTACTS 16
/* The contacts of a ball of `radius` at center (on the gather, else the scene), one per
 * point and normal (a level's duplicated triangles and the edges its neighbours share are
 * one contact each: coll_capsule_overlaps_distinct), the deepest CB_BALL_CONTACTS kept:
 * the crack rule's and the support tests' look around the bottom ball. */
static inline uint32_t cb_ball_overlaps(const cb_ctx_t *c, fm_vec3_t center, float radius,
                                        coll_contact_t out[CB_BALL_CONTACTS])
{
    const uint32_t n =
        c->gather ? coll_gather_capsule_overlaps_distinct(c->gather, center, c->up, radius, 0.0f, out, CB_BALL_CONTACTS)
                  : coll_capsule_overlaps_distinct(c->scene, center, c->up, radius, 0.0f, c->body->settings.read_mask,
                                                   c->body->settings.coll_types, out, CB_BALL_CONTACTS);
    return n > CB_BALL_CONTACTS ? CB_BALL_CONTACTS : n;
}

/** The ray along -up from `origin` by max_dist (the foot ray of the stair step and of the
 *  probe): answered from the step's memory when it is the very ray remembered there;
 *  `remember`: it is remembered. */
static inline bool cb_foot_ray(const cb_ctx_t *c, fm_vec3_t origin, float max_dist, coll_ray_hit_t *hit,
                               bool remember)
{
    cb_mem_t *m = c->mem;
    if (m->ray_valid && m->ray_len == max_dist && m->ray_origin.x == origin.x && m->ray_origin.y == origin.y &&
        m->ray_origin.z == origin.z) {
        if (m->ray_found) *hit = m->ray_hit;
        return m->ray_found;
    }
    bool found = cb_ray(c, origin, v3_scale(c->up, -1.0f), max_dist, hit);
    if (remember) {
        m->ray_valid = true;
        m->ray_found = found;
        m->ray_origin = origin;
        m->ray_len = max_dist;
        if (found) m->ray_hit = *hit;
    }
    return found;
}

/** Answers the down sweep of the sweep capsule, or of its bottom ball, at owner position
 *  pos by len along -up from the remembered stair step's (cb_down_t): true when known
 *  (then *found, and *hit when found). A contact at the very start is not answered. */
static inline bool cb_down_known(const cb_ctx_t *c, fm_vec3_t pos, float len, bool *found, coll_sweep_hit_t *hit)
{
    const cb_down_t *d = &c->mem->down;
    if (!d->valid || d->pos.x != pos.x || d->pos.y != pos.y || d->pos.z != pos.z) return false;
    if (d->hit && d->dist <= len) {
        if (!(d->dist > 0.0f)) return false;
        *hit = d->h;
        hit->t = d->dist / len;
        *found = true;
        return true;
    }
    if (!(len <= d->len)) return false; /* reaches farther than the remembered sweep */
    *found = false;
    return true;
}

/** Where the body is: the owner's position if it is finite (the game may write it between
 *  steps), else the body's own copy. */
static inline fm_vec3_t owner_position(const char_body_t *body)
{
    if (body->owner_pos && v3_finite(*body->owner_pos)) return *body->owner_pos;
    return body->origin;
}
/** Full capsule centre of an owner position. */
static inline fm_vec3_t cb_center(const cb_ctx_t *c, fm_vec3_t pos)
{
    return v3_add(pos, c->body->settings.center_offset);
}
/** Bottom point of the full capsule. */
static inline fm_vec3_t cb_foot(const cb_ctx_t *c, fm_vec3_t pos)
{
    return v3_madd(cb_center(c, pos), c->up, -c->half_height);
}
/** Centre of the shortened sweep capsule. */
static inline fm_vec3_t cb_sweep_center(const cb_ctx_t *c, fm_vec3_t pos)
{
    return v3_madd(cb_center(c, pos), c->up, c->sweep_lift);
}


/** The sweep capsule's down sweep at owner position pos by len along -up (known, or swept),
 *  remembered in the step's memory (cb_down_t). */
bool coll_cb_sweep_down(const cb_ctx_t *c, fm_vec3_t pos, float len, coll_sweep_hit_t *hit);
/** The remembered down sweep's place moved by `by` along up (> 0: up) to pos, unswept, along
 *  the way it came: its first contact is that much farther (or nearer). */
void coll_cb_down_moved(const cb_ctx_t *c, fm_vec3_t pos, float by);

/** Moves by disp with up to max_slides sweep-and-slide iterations, clipping *vel (may be NULL)
 *  by the same planes. grounded: walls only (hits above the step zone act as vertical). */
void coll_cb_slide(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t disp, fm_vec3_t *vel, bool grounded);
/** Swept positional change: moves the sweep capsule by d, stopping skin short of the first
 *  contact (a contact within skin of the end of d counts as the end: the target itself).
 *  Returns the fraction of d travelled (1 when unblocked). */
float coll_cb_move_swept(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t d);
/** coll_cb_move_swept for the stair step's lift and move across (cb_sweep_step) */
float coll_cb_step_swept(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t d);
/** Unswept push by delta, kept only when the sweep capsule then overlaps nothing new or
 *  deeper than before (coll_capsule_overlaps before and after); false: not moved. */
bool coll_cb_push_verified(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t delta);
/** True when the contact is on its triangle's face (within ~2.5 degrees): *face is the face
 *  normal on the contact's side. */
bool coll_cb_face_normal(const coll_sweep_hit_t *hit, fm_vec3_t *face);
/** Pushes the sweep capsule out of whatever it overlaps (Gauss-Seidel over the contacts),
 *  keeping the result only when it overlaps nothing new or deeper than the start did; the
 *  move made is noted in the step's memory (cb_mem_t.push). */
void coll_cb_recover(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t *vel);
/** For a body whose full capsule has no room to stand where it is (its foot in a floor
 *  under an overhang, where the game teleported it): the nearest place across up, swept
 *  to, never against the input, where it stands (4 distances, r/2 to 4r, none beyond the
 *  speed limit's step, x 8 directions; only on that rare step). Airborne (`airborne`: no
 *  walk to keep to) any way, and a place where its foot is in no floor, to fall from,
 *  will do too. Moves *pos there and returns true, or false. The places are tried in a
 *  fixed order from *next on (0: the first); *next is set past the one returned. */
bool coll_cb_stand_search(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t input, bool airborne, int *next);
/** The step could not stand the body anywhere it went, nor at its start (pos, probed
 *  there): the stand search's places, each checked by the probe, moved to as motion (the
 *  velocity says so). True when the body stands nowhere within reach the way its input goes
 *  but could another way, or nowhere at all and its full capsule's bottom ball rests on
 *  nothing: it is wedged, not standing (the caller clears the floor; *pos is the start).
 *  in_h: the input across up; rising: as for the probe. */
bool coll_cb_unwedge(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t start, fm_vec3_t in_h, bool was_grounded,
                     bool rising);
/** Airborne only: the foot point may not pass through walls on its way from old_foot.
 *  True when its way entered a walkable floor (from above): a landing, the probe's job. */
bool coll_cb_foot_guard(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t old_foot, fm_vec3_t *vel);
/** Airborne, after the foot guard moved the body back: the rest of the step's fall (a
 *  length along -up), sliding off an edge the foot point is not over (at most room). */
void coll_cb_guard_fall(const cb_ctx_t *c, fm_vec3_t *pos, float fall, float room);
/** How far the mesh instance stood on last step moved the floor point: false when there is
 *  nothing to carry (not on an instance, or it left the scene). */
bool coll_cb_carry_delta(const cb_ctx_t *c, fm_vec3_t *delta);
/** Moves the body by the carry delta (swept); returns the velocity of the floor point stood
 *  on at the end of that motion. */
fm_vec3_t coll_cb_carry(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t delta);
/** Floor probe after the slide: grounding, steep state, snapping, stair lift, cracks, carry
 *  anchor. Returns false when the body needs a lift onto the floor that the capsule has no
 *  room for (it cannot stand where it is). */
bool coll_cb_probe_floor(const cb_ctx_t *c, fm_vec3_t *pos, bool was_grounded, bool jumping);
/** A rising step (a jump, its probe skipped) ended with the foot under a walkable face in
 *  the step zone that the capsule has no room to be lifted onto: it cannot be there. */
bool coll_cb_rise_sunk(const cb_ctx_t *c, fm_vec3_t pos);

#endif
