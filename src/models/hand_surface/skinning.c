/* Deformation of the hand surface with the skeleton (thesis 4.1.5): rigid links (each
 * vertex with its nearest link, the thesis's method), linear blend skinning, and dual
 * quaternion skinning (Kavan, Collins, Zara, O'Sullivan 2008) with the smooth weights.
 * The transform of a link takes its relaxed (bind) frame to its posed frame. The vertices
 * are taken one influence count at a time (the surface groups them), each count with its
 * own loop, and the link transforms are vectors of columns (see link_matrices). */
#include <math.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

/* Rigid transform of every link as four columns (the rotation's three, then the
 * translation), each a vector of four floats (the fourth 0): the blends and transforms
 * below run four lanes at a time, each lane in the order of the scalar sums
 * ((c0 x + c1 y) + c2 z) + c3, so the results are those of the scalar code. */
typedef float sk__lane4 __attribute__((vector_size(16)));
typedef sk__lane4 link_columns[4];

static void link_matrices(const sk_hand_surface *s, const sk_hand_frames *fr, link_columns *mats)
{
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        sk_mat3d r = sk_m3d_mul(fr->rotation[j], sk_m3d_transpose(s->bind.rotation[j]));
        sk_vec3d o = fr->point[sk_hand_link_point(j)], b = s->bind.point[sk_hand_link_point(j)];
        sk_vec3d t = sk_v3d_sub(o, sk_m3d_apply(r, b));
        for (int c = 0; c < 3; c++)
            mats[j][c] = (sk__lane4){(float)r.m[0][c], (float)r.m[1][c], (float)r.m[2][c], 0.0f};
        mats[j][3] = (sk__lane4){(float)t.x, (float)t.y, (float)t.z, 0.0f};
    }
}

/* Unit dual quaternion of each link: real part (w, x, y, z), dual part. */
typedef float link_dual[8];

static void link_dual_quaternions(link_columns *mats, link_dual *dq)
{
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        const sk__lane4 *m = mats[j];
        sk_mat3d r = {{{m[0][0], m[1][0], m[2][0]},
                       {m[0][1], m[1][1], m[2][1]},
                       {m[0][2], m[1][2], m[2][2]}}};
        sk_quatd q = sk_m3d_to_qd(r);
        sk_quatd t = sk_qd(0, m[3][0], m[3][1], m[3][2]);
        sk_quatd d = sk_qd_mul(t, q);
        dq[j][0] = (float)q.w, dq[j][1] = (float)q.x, dq[j][2] = (float)q.y, dq[j][3] = (float)q.z;
        dq[j][4] = (float)(0.5 * d.w), dq[j][5] = (float)(0.5 * d.x), dq[j][6] = (float)(0.5 * d.y),
        dq[j][7] = (float)(0.5 * d.z);
    }
}

/* p' = M p (with translation) and n' = M n (rotation only), optionally renormalised. */
static inline void transform(const sk__lane4 *restrict m, const float *restrict p,
                             const float *restrict n, float *restrict po, float *restrict no,
                             bool normalise)
{
    sk__lane4 P4 = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3];
    sk__lane4 N4 = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
    po[0] = P4[0], po[1] = P4[1], po[2] = P4[2];
    if (normalise) {
        float len2 = N4[0] * N4[0] + N4[1] * N4[1] + N4[2] * N4[2];
        float inv = len2 > 0.0f ? 1.0f / sqrtf(len2) : 0.0f;
        N4 *= inv;
    }
    no[0] = N4[0], no[1] = N4[1], no[2] = N4[2];
}

/* Linear blend of the vertices vs[lo, hi) that have `n` influences (a constant where it
 * is called, so that each count gets its own unrolled loop). One link moves a vertex by
 * its rigid motion as it is; a blend renormalises the normal. */
static inline void lbs_group(const sk_hand_surface *s, link_columns *mats,
                             const uint16_t *restrict L, const float *restrict W,
                             const uint32_t *restrict vs, size_t lo, size_t hi, int n,
                             float *restrict pos, float *restrict nrm)
{
    const float *P = s->mesh.positions, *N = s->mesh.normals;
    for (size_t i = lo; i < hi; i++) {
        size_t v = vs ? vs[i] : i;
        const uint16_t *l = L + 4 * v;
        const float *w = W + 4 * v;
        if (n == 1) {
            transform(mats[l[0]], P + 3 * v, N + 3 * v, pos + 3 * v, nrm + 3 * v, false);
            continue;
        }
        link_columns m;
        for (int c = 0; c < 4; c++) m[c] = w[0] * mats[l[0]][c];
        for (int k = 1; k < n; k++)
            for (int c = 0; c < 4; c++) m[c] += w[k] * mats[l[k]][c];
        transform(m, P + 3 * v, N + 3 * v, pos + 3 * v, nrm + 3 * v, true);
    }
}

/* Dual quaternion blend of the vertices vs[lo, hi) with `n` (>= 2) influences. */
static inline void dqs_group(const sk_hand_surface *s, link_dual *dq, const uint32_t *restrict vs,
                             size_t lo, size_t hi, int n, float *restrict pos, float *restrict nrm)
{
    const float *P = s->mesh.positions, *N = s->mesh.normals;
    const uint16_t *L = s->links[1];
    const float *W = s->weights[1];
    for (size_t i = lo; i < hi; i++) {
        size_t v = vs[i];
        const uint16_t *l = L + 4 * v;
        const float *w = W + 4 * v;
        const float *q0 = dq[l[0]];
        float b[8];
        for (int k = 0; k < 8; k++) b[k] = w[0] * q0[k];
        for (int k = 1; k < n; k++) {
            const float *q = dq[l[k]];
            /* the shortest path: quaternions in the first one's hemisphere */
            float wk =
                q0[0] * q[0] + q0[1] * q[1] + q0[2] * q[2] + q0[3] * q[3] < 0.0f ? -w[k] : w[k];
            for (int c = 0; c < 8; c++) b[c] += wk * q[c];
        }
        float inv = 1.0f / sqrtf(b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3]);
        float qw = b[0] * inv, qx = b[1] * inv, qy = b[2] * inv, qz = b[3] * inv;
        float dw = b[4] * inv, dx = b[5] * inv, dy = b[6] * inv, dz = b[7] * inv;
        /* translation 2 d q* */
        float tx = 2.0f * (-dw * qx + dx * qw - dy * qz + dz * qy);
        float ty = 2.0f * (-dw * qy + dx * qz + dy * qw - dz * qx);
        float tz = 2.0f * (-dw * qz - dx * qy + dy * qx + dz * qw);
        float r00 = 1 - 2 * (qy * qy + qz * qz), r01 = 2 * (qx * qy - qw * qz),
              r02 = 2 * (qx * qz + qw * qy);
        float r10 = 2 * (qx * qy + qw * qz), r11 = 1 - 2 * (qx * qx + qz * qz),
              r12 = 2 * (qy * qz - qw * qx);
        float r20 = 2 * (qx * qz - qw * qy), r21 = 2 * (qy * qz + qw * qx),
              r22 = 1 - 2 * (qx * qx + qy * qy);
        link_columns m = {{r00, r10, r20, 0.0f},
                          {r01, r11, r21, 0.0f},
                          {r02, r12, r22, 0.0f},
                          {tx, ty, tz, 0.0f}};
        transform(m, P + 3 * v, N + 3 * v, pos + 3 * v, nrm + 3 * v, false);
    }
}

/* Part c of `chunks` of every influence group. */
static void deform_chunk(const sk_hand_surface *s, link_columns *mats, link_dual *dq,
                         sk_hand_skinning method, int c, int chunks, float *pos, float *nrm)
{
    if (method == SK_HAND_SKINNING_RIGID) {
        size_t V = s->mesh.vertex_count;
        lbs_group(s, mats, s->links[0], s->weights[0], NULL, V * (size_t)c / (size_t)chunks,
                  V * (size_t)(c + 1) / (size_t)chunks, 1, pos, nrm);
        return;
    }
    const uint32_t *vs = s->by_influence, *first = s->influence_first;
    for (int n = 1; n <= 4; n++) {
        size_t a = first[n - 1], count = first[n] - a;
        size_t lo = a + count * (size_t)c / (size_t)chunks,
               hi = a + count * (size_t)(c + 1) / (size_t)chunks;
        const uint16_t *L = s->links[1];
        const float *W = s->weights[1];
        /* one link: its rigid motion, the same as the dual quaternion's */
        if (n == 1)
            lbs_group(s, mats, L, W, vs, lo, hi, 1, pos, nrm);
        else if (method == SK_HAND_SKINNING_DQS)
            dqs_group(s, dq, vs, lo, hi, n, pos, nrm);
        else if (n == 2)
            lbs_group(s, mats, L, W, vs, lo, hi, 2, pos, nrm);
        else if (n == 3)
            lbs_group(s, mats, L, W, vs, lo, hi, 3, pos, nrm);
        else
            lbs_group(s, mats, L, W, vs, lo, hi, 4, pos, nrm);
    }
}

#define PARALLEL_MIN_VERTICES 20000

void sk_hand_surface_deform(const sk_hand_surface *s, const sk_hand_frames *frames,
                            sk_hand_skinning method, float *positions, float *normals)
{
    link_columns mats[SK_HAND_LINK_COUNT];
    link_matrices(s, frames, mats);
    size_t V = s->mesh.vertex_count;
    if (method == SK_HAND_SKINNING_DEFAULT) method = SK_HAND_SKINNING_DQS;
    link_dual dq[SK_HAND_LINK_COUNT];
    if (method == SK_HAND_SKINNING_DQS) link_dual_quaternions(mats, dq);
    int chunks = V >= PARALLEL_MIN_VERTICES ? 64 : 1;
#pragma omp parallel for schedule(static) if (chunks > 1)
    for (int c = 0; c < chunks; c++)
        deform_chunk(s, mats, dq, method, c, chunks, positions, normals);
}

sk_result sk_hand_surface_pose(const sk_hand_surface *s, const double dofs[SK_HAND_DOF_COUNT],
                               sk_hand_skinning method, sk_mesh *out, sk_error *err)
{
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        if (!isfinite(dofs[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s is not a finite number",
                           sk_hand_dof(i)->name);
    if ((int)method < 0 || method > SK_HAND_SKINNING_DQS)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "skinning method %d is not rigid, lbs or dqs", (int)method);
    sk_result r =
        sk_mesh_create(out, s->mesh.vertex_count, s->mesh.triangle_count, SK_MESH_NORMALS, err);
    if (r != SK_OK) return r;
    memcpy(out->indices, s->mesh.indices, 3 * s->mesh.triangle_count * sizeof *out->indices);
    sk_hand_frames fr;
    sk_hand_forward(&s->skeleton, dofs, &fr);
    sk_hand_surface_deform(s, &fr, method, out->positions, out->normals);
    const sk_mesh_attribute *nail = sk_mesh_find_attribute(&s->mesh, "nail");
    float *data;
    if (nail && (r = sk_mesh_add_attribute(out, "nail", 1, &data, err)) == SK_OK)
        memcpy(data, nail->data, s->mesh.vertex_count * sizeof *data);
    if (r != SK_OK) sk_mesh_free(out);
    return r;
}
