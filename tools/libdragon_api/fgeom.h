/*
 * Stand-in for libdragon's <fgeom.h> (preview branch), written for charbody64's CI from
 * libdragon's documented API: the same types (fm_vec3_t, fm_vec4_t, fm_quat_t, fm_mat4_t),
 * the same functions with the same signatures, `inline` (C99, external copies in the
 * library) where libdragon's are, declared only where libdragon's are out of line. The
 * bodies are ours and simple. Like the real header it uses empty initializer braces
 * `(fm_vec3_t){}`, so it compiles under -pedantic -Werror only as a system header
 * (-isystem). Never linked into anything.
 */
#ifndef LIBDRAGON_FGEOM_H
#define LIBDRAGON_FGEOM_H

#include <math.h>
#include <stdbool.h>
#include <memory.h>
#include "fmath.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef union { struct { float x, y, z; }; float v[3]; } fm_vec3_t;
typedef union { struct { float x, y, z, w; }; float v[4]; } fm_vec4_t;
typedef union { struct { float x, y, z, w; }; float v[4]; } fm_quat_t;
typedef struct { float m[4][4]; } fm_mat4_t;

/* ---- vec3 ---- */
inline void fm_vec3_negate(fm_vec3_t *out, const fm_vec3_t *v) { for (int i = 0; i < 3; i++) out->v[i] = -v->v[i]; }
inline void fm_vec3_add(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b) { for (int i = 0; i < 3; i++) out->v[i] = a->v[i] + b->v[i]; }
inline void fm_vec3_sub(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b) { for (int i = 0; i < 3; i++) out->v[i] = a->v[i] - b->v[i]; }
inline void fm_vec3_mul(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b) { for (int i = 0; i < 3; i++) out->v[i] = a->v[i] * b->v[i]; }
inline void fm_vec3_div(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b) { for (int i = 0; i < 3; i++) out->v[i] = a->v[i] / b->v[i]; }
inline void fm_vec3_scale(fm_vec3_t *out, const fm_vec3_t *a, float s) { for (int i = 0; i < 3; i++) out->v[i] = a->v[i] * s; }
inline float fm_vec3_dot(const fm_vec3_t *a, const fm_vec3_t *b) { return a->x * b->x + a->y * b->y + a->z * b->z; }
inline float fm_vec3_len2(const fm_vec3_t *a) { return fm_vec3_dot(a, a); }
inline float fm_vec3_len(const fm_vec3_t *a) { return sqrtf(fm_vec3_len2(a)); }
inline float fm_vec3_distance2(const fm_vec3_t *a, const fm_vec3_t *b)
{
    fm_vec3_t d;
    fm_vec3_sub(&d, a, b);
    return fm_vec3_len2(&d);
}
inline float fm_vec3_distance(const fm_vec3_t *a, const fm_vec3_t *b) { return sqrtf(fm_vec3_distance2(a, b)); }
inline void fm_vec3_norm(fm_vec3_t *out, const fm_vec3_t *a)
{
    float l = fm_vec3_len(a);
    if (l < FM_EPSILON) { *out = (fm_vec3_t){}; return; }
    fm_vec3_scale(out, a, 1.0f / l);
}
inline void fm_vec3_cross(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b)
{
    fm_vec3_t r = {{ a->y * b->z - a->z * b->y, a->z * b->x - a->x * b->z, a->x * b->y - a->y * b->x }};
    *out = r;
}
inline void fm_vec3_lerp(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b, float t)
{
    for (int i = 0; i < 3; i++) out->v[i] = fm_lerp(a->v[i], b->v[i], t);
}
void fm_vec3_reflect(fm_vec3_t *out, const fm_vec3_t *i, const fm_vec3_t *n);
bool fm_vec3_refract(fm_vec3_t *out, const fm_vec3_t *i, const fm_vec3_t *n, float eta);
void fm_vec3_rotate(fm_vec3_t *out, const fm_vec3_t *i, const fm_quat_t *q);

/* ---- quat ---- */
inline void fm_quat_identity(fm_quat_t *out) { *out = (fm_quat_t){{ 0, 0, 0, 1 }}; }
void fm_quat_from_euler(fm_quat_t *out, const float euler[3]);
void fm_quat_from_euler_zyx(fm_quat_t *out, float x, float y, float z);
inline void fm_quat_from_axis_angle(fm_quat_t *out, const fm_vec3_t *axis, float angle)
{
    float s, c;
    fm_sincosf(angle * 0.5f, &s, &c);
    *out = (fm_quat_t){{ axis->x * s, axis->y * s, axis->z * s, c }};
}
void fm_quat_mul(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b);
void fm_quat_rotate(fm_quat_t *out, const fm_quat_t *q, const fm_vec3_t *axis, float angle);
inline float fm_quat_dot(const fm_quat_t *a, const fm_quat_t *b) { return a->x * b->x + a->y * b->y + a->z * b->z + a->w * b->w; }
inline void fm_quat_inverse(fm_quat_t *out, const fm_quat_t *q)
{
    float k = 1.0f / fm_quat_dot(q, q);
    *out = (fm_quat_t){{ -q->x * k, -q->y * k, -q->z * k, q->w * k }};
}
inline void fm_quat_norm(fm_quat_t *out, const fm_quat_t *q)
{
    float l = sqrtf(fm_quat_dot(q, q));
    if (l < FM_EPSILON) { fm_quat_identity(out); return; }
    *out = (fm_quat_t){{ q->x / l, q->y / l, q->z / l, q->w / l }};
}
void fm_quat_nlerp(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b, float t);
void fm_quat_slerp(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b, float t);

/* ---- mat4 ---- */
inline void fm_mat4_identity(fm_mat4_t *out)
{
    *out = (fm_mat4_t){};
    for (int i = 0; i < 4; i++) out->m[i][i] = 1;
}
inline void fm_mat4_scale(fm_mat4_t *out, const fm_vec3_t *scale)
{
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 3; r++) out->m[c][r] *= scale->v[r];
}
inline void fm_mat4_translate(fm_mat4_t *out, const fm_vec3_t *translate)
{
    for (int r = 0; r < 3; r++) out->m[3][r] += translate->v[r];
}
void fm_mat4_rotate(fm_mat4_t *out, const fm_quat_t *rotation);
void fm_mat4_from_axis_angle(fm_mat4_t *out, const fm_vec3_t *axis, float angle);
void fm_mat4_from_srt(fm_mat4_t *out, const fm_vec3_t *scale, const fm_quat_t *quat, const fm_vec3_t *translate);
void fm_mat4_from_srt_euler(fm_mat4_t *out, const fm_vec3_t *scale, const float euler[3], const fm_vec3_t *translate);
inline void fm_mat4_from_rt(fm_mat4_t *out, const fm_quat_t *quat, const fm_vec3_t *translate)
{
    const fm_vec3_t one = {{ 1, 1, 1 }};
    fm_mat4_from_srt(out, &one, quat, translate);
}
inline void fm_mat4_from_rt_euler(fm_mat4_t *out, const float euler[3], const fm_vec3_t *translate)
{
    const fm_vec3_t one = {{ 1, 1, 1 }};
    fm_mat4_from_srt_euler(out, &one, euler, translate);
}
inline void fm_mat4_from_translation(fm_mat4_t *out, const fm_vec3_t *translate)
{
    fm_mat4_identity(out);
    fm_mat4_translate(out, translate);
}
inline void fm_mat4_from_rotation(fm_mat4_t *out, const fm_quat_t *rotation)
{
    const fm_vec3_t zero = {{ 0, 0, 0 }};
    fm_mat4_from_rt(out, rotation, &zero);
}
inline void fm_mat4_from_scale(fm_mat4_t *out, const fm_vec3_t *scale)
{
    fm_mat4_identity(out);
    fm_mat4_scale(out, scale);
}
inline void fm_mat4_mul(fm_mat4_t *out, const fm_mat4_t *a, const fm_mat4_t *b)
{
    fm_mat4_t r;
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) {
            float s = 0;
            for (int k = 0; k < 4; k++) s += a->m[k][row] * b->m[c][k];
            r.m[c][row] = s;
        }
    *out = r;
}
inline void fm_mat4_transpose(fm_mat4_t *out, const fm_mat4_t *m)
{
    fm_mat4_t r;
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) r.m[c][row] = m->m[row][c];
    *out = r;
}
float fm_mat4_det(const fm_mat4_t *m);
void fm_mat4_inverse(fm_mat4_t *out, const fm_mat4_t *m);
void fm_mat4_affine_to_normal_mat(fm_mat4_t *out, const fm_mat4_t *m);
void fm_mat4_look(fm_mat4_t *out, const fm_vec3_t *eye, const fm_vec3_t *dir, const fm_vec3_t *up);
void fm_mat4_lookat(fm_mat4_t *out, const fm_vec3_t *eye, const fm_vec3_t *target, const fm_vec3_t *up);
inline void fm_mat4_mul_vec3(fm_vec4_t *out, const fm_mat4_t *m, const fm_vec3_t *v)
{
    for (int i = 0; i < 4; i++)
        out->v[i] = m->m[0][i] * v->x + m->m[1][i] * v->y + m->m[2][i] * v->z + m->m[3][i];
}
inline void fm_mat4_mul_vec4(fm_vec4_t *out, const fm_mat4_t *m, const fm_vec4_t *v)
{
    fm_vec4_t r;
    for (int i = 0; i < 4; i++)
        r.v[i] = m->m[0][i] * v->x + m->m[1][i] * v->y + m->m[2][i] * v->z + m->m[3][i] * v->w;
    *out = r;
}

#ifdef __cplusplus
}
#endif
#endif
