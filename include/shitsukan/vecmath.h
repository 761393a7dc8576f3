/* shitsukan small vector math: 2/3/4-vectors, 3x3 and 4x4 matrices, quaternions, in
 * float (per-pixel, per-vertex data) and double (solves, kinematic chains).
 *
 * All functions are static inline and pure (thread-safe). Matrices are row-major,
 * m[row][col], and act on column vectors: y = M x. Quaternions are (w, x, y, z) with
 * the Hamilton product, and rotate vectors as q v q*. */
#ifndef SHITSUKAN_VECMATH_H
#define SHITSUKAN_VECMATH_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SK_PI 3.14159265358979323846
#define SK_PI_F 3.14159265358979323846f
#define SK_DEG_TO_RAD (SK_PI / 180.0)
#define SK_RAD_TO_DEG (180.0 / SK_PI)

typedef struct sk_vec2f {
    float x, y;
} sk_vec2f;
typedef struct sk_vec3f {
    float x, y, z;
} sk_vec3f;
typedef struct sk_vec4f {
    float x, y, z, w;
} sk_vec4f;
typedef struct sk_vec2d {
    double x, y;
} sk_vec2d;
typedef struct sk_vec3d {
    double x, y, z;
} sk_vec3d;
typedef struct sk_mat3f {
    float m[3][3];
} sk_mat3f;
typedef struct sk_mat4f {
    float m[4][4];
} sk_mat4f;
typedef struct sk_mat3d {
    double m[3][3];
} sk_mat3d;
typedef struct sk_mat4d {
    double m[4][4];
} sk_mat4d;
typedef struct sk_quatf {
    float w, x, y, z;
} sk_quatf;
typedef struct sk_quatd {
    double w, x, y, z;
} sk_quatd;

/* ------------------------------------------------------------ scalar helpers */
static inline float sk_clampf(float v, float lo, float hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}
static inline double sk_clampd(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}
static inline float sk_lerpf(float a, float b, float t) { return a + (b - a) * t; }
static inline double sk_lerpd(double a, double b, double t) { return a + (b - a) * t; }
static inline float sk_smoothstepf(float e0, float e1, float x)
{
    float t = sk_clampf((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}
/* Floor modulo: result in [0, m) for m > 0. */
static inline double sk_fmodpos(double a, double m)
{
    double r = fmod(a, m);
    return r < 0.0 ? r + m : r;
}
static inline int sk_imodpos(int a, int m)
{
    int r = a % m;
    return r < 0 ? r + m : r;
}

/* ------------------------------------------------------------------ vec2f */
static inline sk_vec2f sk_v2f(float x, float y)
{
    sk_vec2f v = {x, y};
    return v;
}
static inline sk_vec2f sk_v2f_add(sk_vec2f a, sk_vec2f b) { return sk_v2f(a.x + b.x, a.y + b.y); }
static inline sk_vec2f sk_v2f_sub(sk_vec2f a, sk_vec2f b) { return sk_v2f(a.x - b.x, a.y - b.y); }
static inline sk_vec2f sk_v2f_scale(sk_vec2f a, float s) { return sk_v2f(a.x * s, a.y * s); }
static inline float sk_v2f_dot(sk_vec2f a, sk_vec2f b) { return a.x * b.x + a.y * b.y; }
static inline float sk_v2f_cross(sk_vec2f a, sk_vec2f b) { return a.x * b.y - a.y * b.x; }
static inline float sk_v2f_length(sk_vec2f a) { return sqrtf(a.x * a.x + a.y * a.y); }

/* ------------------------------------------------------------------ vec2d */
static inline sk_vec2d sk_v2d(double x, double y)
{
    sk_vec2d v = {x, y};
    return v;
}
static inline sk_vec2d sk_v2d_add(sk_vec2d a, sk_vec2d b) { return sk_v2d(a.x + b.x, a.y + b.y); }
static inline sk_vec2d sk_v2d_sub(sk_vec2d a, sk_vec2d b) { return sk_v2d(a.x - b.x, a.y - b.y); }
static inline sk_vec2d sk_v2d_scale(sk_vec2d a, double s) { return sk_v2d(a.x * s, a.y * s); }
static inline double sk_v2d_dot(sk_vec2d a, sk_vec2d b) { return a.x * b.x + a.y * b.y; }
static inline double sk_v2d_cross(sk_vec2d a, sk_vec2d b) { return a.x * b.y - a.y * b.x; }
static inline double sk_v2d_length(sk_vec2d a) { return sqrt(a.x * a.x + a.y * a.y); }
static inline sk_vec2d sk_v2d_perp(sk_vec2d a) { return sk_v2d(-a.y, a.x); }

/* ------------------------------------------------------------------ vec3f */
static inline sk_vec3f sk_v3f(float x, float y, float z)
{
    sk_vec3f v = {x, y, z};
    return v;
}
/* The vector of three consecutive floats (a mesh's positions, normals). */
static inline sk_vec3f sk_v3f_load(const float a[3]) { return sk_v3f(a[0], a[1], a[2]); }
static inline sk_vec3f sk_v3f_add(sk_vec3f a, sk_vec3f b)
{
    return sk_v3f(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline sk_vec3f sk_v3f_sub(sk_vec3f a, sk_vec3f b)
{
    return sk_v3f(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline sk_vec3f sk_v3f_mul(sk_vec3f a, sk_vec3f b)
{
    return sk_v3f(a.x * b.x, a.y * b.y, a.z * b.z);
}
static inline sk_vec3f sk_v3f_scale(sk_vec3f a, float s)
{
    return sk_v3f(a.x * s, a.y * s, a.z * s);
}
static inline sk_vec3f sk_v3f_neg(sk_vec3f a) { return sk_v3f(-a.x, -a.y, -a.z); }
static inline float sk_v3f_dot(sk_vec3f a, sk_vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline sk_vec3f sk_v3f_cross(sk_vec3f a, sk_vec3f b)
{
    return sk_v3f(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline float sk_v3f_length(sk_vec3f a) { return sqrtf(sk_v3f_dot(a, a)); }
/* Unit vector along a; the zero vector stays zero. */
static inline sk_vec3f sk_v3f_normalize(sk_vec3f a)
{
    float l = sk_v3f_length(a);
    return l > 0.0f ? sk_v3f_scale(a, 1.0f / l) : a;
}
static inline sk_vec3f sk_v3f_lerp(sk_vec3f a, sk_vec3f b, float t)
{
    return sk_v3f(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
}
/* Mirror direction of d about unit normal n: d - 2 (d.n) n. */
static inline sk_vec3f sk_v3f_reflect(sk_vec3f d, sk_vec3f n)
{
    return sk_v3f_sub(d, sk_v3f_scale(n, 2.0f * sk_v3f_dot(d, n)));
}

/* ------------------------------------------------------------------ vec3d */
static inline sk_vec3d sk_v3d(double x, double y, double z)
{
    sk_vec3d v = {x, y, z};
    return v;
}
static inline sk_vec3d sk_v3d_add(sk_vec3d a, sk_vec3d b)
{
    return sk_v3d(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline sk_vec3d sk_v3d_sub(sk_vec3d a, sk_vec3d b)
{
    return sk_v3d(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline sk_vec3d sk_v3d_scale(sk_vec3d a, double s)
{
    return sk_v3d(a.x * s, a.y * s, a.z * s);
}
static inline double sk_v3d_dot(sk_vec3d a, sk_vec3d b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline sk_vec3d sk_v3d_cross(sk_vec3d a, sk_vec3d b)
{
    return sk_v3d(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double sk_v3d_length(sk_vec3d a) { return sqrt(sk_v3d_dot(a, a)); }
static inline sk_vec3d sk_v3d_normalize(sk_vec3d a)
{
    double l = sk_v3d_length(a);
    return l > 0.0 ? sk_v3d_scale(a, 1.0 / l) : a;
}
static inline sk_vec3f sk_v3d_to_f(sk_vec3d a)
{
    return sk_v3f((float)a.x, (float)a.y, (float)a.z);
}
static inline sk_vec3d sk_v3f_to_d(sk_vec3f a) { return sk_v3d(a.x, a.y, a.z); }

/* ----------------------------------------------------------------- mat3f */
static inline sk_mat3f sk_m3f_identity(void)
{
    sk_mat3f r = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    return r;
}
static inline sk_mat3f sk_m3f_mul(sk_mat3f a, sk_mat3f b)
{
    sk_mat3f r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
}
static inline sk_vec3f sk_m3f_apply(sk_mat3f a, sk_vec3f v)
{
    return sk_v3f(a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
                  a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
                  a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z);
}
static inline sk_mat3f sk_m3f_transpose(sk_mat3f a)
{
    sk_mat3f r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = a.m[j][i];
    return r;
}

/* ----------------------------------------------------------------- mat3d */
static inline sk_mat3d sk_m3d_identity(void)
{
    sk_mat3d r = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    return r;
}
static inline sk_mat3d sk_m3d_mul(sk_mat3d a, sk_mat3d b)
{
    sk_mat3d r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
}
static inline sk_vec3d sk_m3d_apply(sk_mat3d a, sk_vec3d v)
{
    return sk_v3d(a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
                  a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
                  a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z);
}
static inline sk_mat3d sk_m3d_transpose(sk_mat3d a)
{
    sk_mat3d r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = a.m[j][i];
    return r;
}
/* Right-handed rotations by angle (radians) about the X, Y and Z axes. */
static inline sk_mat3d sk_m3d_rot_x(double a)
{
    double c = cos(a), s = sin(a);
    sk_mat3d r = {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
    return r;
}
static inline sk_mat3d sk_m3d_rot_y(double a)
{
    double c = cos(a), s = sin(a);
    sk_mat3d r = {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
    return r;
}
static inline sk_mat3d sk_m3d_rot_z(double a)
{
    double c = cos(a), s = sin(a);
    sk_mat3d r = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
    return r;
}
static inline double sk_m3d_det(sk_mat3d a)
{
    return a.m[0][0] * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]) -
           a.m[0][1] * (a.m[1][0] * a.m[2][2] - a.m[1][2] * a.m[2][0]) +
           a.m[0][2] * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
}
/* The solution x of a x = b by Cramer's rule, given det = sk_m3d_det(a) (non-zero): the
 * library's one 3x3 solve (each x[c] is the determinant of a with column c replaced by
 * b, over det). */
static inline sk_vec3d sk_m3d_solve_cramer(sk_mat3d a, sk_vec3d b, double det)
{
    double x[3], rhs[3] = {b.x, b.y, b.z};
    for (int col = 0; col < 3; col++) {
        sk_mat3d m = a;
        for (int row = 0; row < 3; row++) m.m[row][col] = rhs[row];
        x[col] = sk_m3d_det(m) / det;
    }
    sk_vec3d r = {x[0], x[1], x[2]};
    return r;
}
static inline sk_mat3f sk_m3d_to_f(sk_mat3d a)
{
    sk_mat3f r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = (float)a.m[i][j];
    return r;
}

/* ----------------------------------------------------------------- mat4f */
static inline sk_mat4f sk_m4f_identity(void)
{
    sk_mat4f r = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    return r;
}
static inline sk_mat4f sk_m4f_mul(sk_mat4f a, sk_mat4f b)
{
    sk_mat4f r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j] +
                        a.m[i][3] * b.m[3][j];
    return r;
}
/* Transforms a point (w = 1) by an affine matrix. */
static inline sk_vec3f sk_m4f_apply_point(sk_mat4f a, sk_vec3f p)
{
    return sk_v3f(a.m[0][0] * p.x + a.m[0][1] * p.y + a.m[0][2] * p.z + a.m[0][3],
                  a.m[1][0] * p.x + a.m[1][1] * p.y + a.m[1][2] * p.z + a.m[1][3],
                  a.m[2][0] * p.x + a.m[2][1] * p.y + a.m[2][2] * p.z + a.m[2][3]);
}
/* Transforms a direction (w = 0). */
static inline sk_vec3f sk_m4f_apply_dir(sk_mat4f a, sk_vec3f d)
{
    return sk_v3f(a.m[0][0] * d.x + a.m[0][1] * d.y + a.m[0][2] * d.z,
                  a.m[1][0] * d.x + a.m[1][1] * d.y + a.m[1][2] * d.z,
                  a.m[2][0] * d.x + a.m[2][1] * d.y + a.m[2][2] * d.z);
}
static inline sk_mat4f sk_m4f_translation(sk_vec3f t)
{
    sk_mat4f r = sk_m4f_identity();
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}
static inline sk_mat4f sk_m4f_scaling(sk_vec3f s)
{
    sk_mat4f r = sk_m4f_identity();
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}
/* Affine matrix from a rotation and a translation. */
static inline sk_mat4f sk_m4f_from_rt(sk_mat3f rot, sk_vec3f t)
{
    sk_mat4f r = sk_m4f_identity();
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = rot.m[i][j];
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}
/* Inverse of an affine matrix (last row 0 0 0 1). Returns 0 if singular. */
static inline int sk_m4f_affine_inverse(sk_mat4f a, sk_mat4f *out)
{
    double c00 = (double)a.m[1][1] * a.m[2][2] - (double)a.m[1][2] * a.m[2][1];
    double c01 = (double)a.m[1][2] * a.m[2][0] - (double)a.m[1][0] * a.m[2][2];
    double c02 = (double)a.m[1][0] * a.m[2][1] - (double)a.m[1][1] * a.m[2][0];
    double det = a.m[0][0] * c00 + a.m[0][1] * c01 + a.m[0][2] * c02;
    if (det == 0.0 || !isfinite(det)) return 0;
    double id = 1.0 / det;
    double inv[3][3];
    inv[0][0] = c00 * id;
    inv[1][0] = c01 * id;
    inv[2][0] = c02 * id;
    inv[0][1] = ((double)a.m[0][2] * a.m[2][1] - (double)a.m[0][1] * a.m[2][2]) * id;
    inv[1][1] = ((double)a.m[0][0] * a.m[2][2] - (double)a.m[0][2] * a.m[2][0]) * id;
    inv[2][1] = ((double)a.m[0][1] * a.m[2][0] - (double)a.m[0][0] * a.m[2][1]) * id;
    inv[0][2] = ((double)a.m[0][1] * a.m[1][2] - (double)a.m[0][2] * a.m[1][1]) * id;
    inv[1][2] = ((double)a.m[0][2] * a.m[1][0] - (double)a.m[0][0] * a.m[1][2]) * id;
    inv[2][2] = ((double)a.m[0][0] * a.m[1][1] - (double)a.m[0][1] * a.m[1][0]) * id;
    sk_mat4f r = sk_m4f_identity();
    for (int i = 0; i < 3; i++) {
        double t = 0.0;
        for (int j = 0; j < 3; j++) {
            r.m[i][j] = (float)inv[i][j];
            t -= inv[i][j] * a.m[j][3];
        }
        r.m[i][3] = (float)t;
    }
    *out = r;
    return 1;
}

/* ----------------------------------------------------------- quaternions */
static inline sk_quatd sk_qd(double w, double x, double y, double z)
{
    sk_quatd q = {w, x, y, z};
    return q;
}
static inline sk_quatd sk_qd_identity(void) { return sk_qd(1, 0, 0, 0); }
static inline sk_quatd sk_qd_mul(sk_quatd a, sk_quatd b)
{
    return sk_qd(a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
                 a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                 a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                 a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w);
}
static inline sk_quatd sk_qd_conj(sk_quatd q) { return sk_qd(q.w, -q.x, -q.y, -q.z); }
static inline double sk_qd_dot(sk_quatd a, sk_quatd b)
{
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline sk_quatd sk_qd_normalize(sk_quatd q)
{
    double l = sqrt(sk_qd_dot(q, q));
    return l > 0.0 ? sk_qd(q.w / l, q.x / l, q.y / l, q.z / l) : sk_qd_identity();
}
/* Rotation by `angle` radians about the unit `axis`. */
static inline sk_quatd sk_qd_axis_angle(sk_vec3d axis, double angle)
{
    double s = sin(0.5 * angle);
    return sk_qd(cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s);
}
static inline sk_vec3d sk_qd_rotate(sk_quatd q, sk_vec3d v)
{
    /* v' = v + 2 w (u x v) + 2 u x (u x v), u = vector part */
    sk_vec3d u = sk_v3d(q.x, q.y, q.z);
    sk_vec3d t = sk_v3d_scale(sk_v3d_cross(u, v), 2.0);
    return sk_v3d_add(sk_v3d_add(v, sk_v3d_scale(t, q.w)), sk_v3d_cross(u, t));
}
static inline sk_mat3d sk_qd_to_m3d(sk_quatd q)
{
    double w = q.w, x = q.x, y = q.y, z = q.z;
    sk_mat3d r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                   {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                   {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
    return r;
}
/* Quaternion of a proper rotation matrix (Shepperd's method, stable for all angles). */
static inline sk_quatd sk_m3d_to_qd(sk_mat3d m)
{
    double tr = m.m[0][0] + m.m[1][1] + m.m[2][2];
    sk_quatd q;
    if (tr > 0.0) {
        double s = 2.0 * sqrt(tr + 1.0);
        q = sk_qd(0.25 * s, (m.m[2][1] - m.m[1][2]) / s, (m.m[0][2] - m.m[2][0]) / s,
                  (m.m[1][0] - m.m[0][1]) / s);
    } else if (m.m[0][0] > m.m[1][1] && m.m[0][0] > m.m[2][2]) {
        double s = 2.0 * sqrt(1.0 + m.m[0][0] - m.m[1][1] - m.m[2][2]);
        q = sk_qd((m.m[2][1] - m.m[1][2]) / s, 0.25 * s, (m.m[0][1] + m.m[1][0]) / s,
                  (m.m[0][2] + m.m[2][0]) / s);
    } else if (m.m[1][1] > m.m[2][2]) {
        double s = 2.0 * sqrt(1.0 + m.m[1][1] - m.m[0][0] - m.m[2][2]);
        q = sk_qd((m.m[0][2] - m.m[2][0]) / s, (m.m[0][1] + m.m[1][0]) / s, 0.25 * s,
                  (m.m[1][2] + m.m[2][1]) / s);
    } else {
        double s = 2.0 * sqrt(1.0 + m.m[2][2] - m.m[0][0] - m.m[1][1]);
        q = sk_qd((m.m[1][0] - m.m[0][1]) / s, (m.m[0][2] + m.m[2][0]) / s,
                  (m.m[1][2] + m.m[2][1]) / s, 0.25 * s);
    }
    return sk_qd_normalize(q);
}
/* Spherical linear interpolation along the shorter arc. */
static inline sk_quatd sk_qd_slerp(sk_quatd a, sk_quatd b, double t)
{
    double d = sk_qd_dot(a, b);
    if (d < 0.0) {
        b = sk_qd(-b.w, -b.x, -b.y, -b.z);
        d = -d;
    }
    if (d > 0.9995) {
        return sk_qd_normalize(sk_qd(a.w + (b.w - a.w) * t, a.x + (b.x - a.x) * t,
                                     a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t));
    }
    double th = acos(d), s = sin(th);
    double wa = sin((1.0 - t) * th) / s, wb = sin(t * th) / s;
    return sk_qd(wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y,
                 wa * a.z + wb * b.z);
}
static inline sk_quatf sk_qd_to_f(sk_quatd q)
{
    sk_quatf r = {(float)q.w, (float)q.x, (float)q.y, (float)q.z};
    return r;
}
static inline sk_vec3f sk_qf_rotate(sk_quatf q, sk_vec3f v)
{
    sk_vec3f u = sk_v3f(q.x, q.y, q.z);
    sk_vec3f t = sk_v3f_scale(sk_v3f_cross(u, v), 2.0f);
    return sk_v3f_add(sk_v3f_add(v, sk_v3f_scale(t, q.w)), sk_v3f_cross(u, t));
}

/* Builds an orthonormal basis (t, b) perpendicular to unit n (Duff et al. 2017,
 * branchless ONB), so that (t, b, n) is right-handed. */
static inline void sk_v3f_basis(sk_vec3f n, sk_vec3f *t, sk_vec3f *b)
{
    float sign = copysignf(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float bb = n.x * n.y * a;
    *t = sk_v3f(1.0f + sign * n.x * n.x * a, sign * bb, -sign * n.x);
    *b = sk_v3f(bb, sign + n.y * n.y * a, -n.y);
}

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_VECMATH_H */
