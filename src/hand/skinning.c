/* Deformation of the hand surface with the skeleton (thesis 4.1.5): rigid links (each
 * vertex with its nearest link, the thesis's method), linear blend skinning, and dual
 * quaternion skinning (Kavan, Collins, Zara, O'Sullivan 2008) with the smooth weights.
 * The transform of a link takes its relaxed (bind) frame to its posed frame. */
#include <math.h>
#include <string.h>

#include "hand/surface_private.h"

/* Rigid transform of every link: 3x4 row-major (rotation | translation), float. */
static void link_matrices(const sk_hand_surface *s, const sk_hand_frames *fr, float mats[SK_HAND_LINK_COUNT][12])
{
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        sk_mat3d r = sk_m3d_mul(fr->rotation[j], sk_m3d_transpose(s->bind.rotation[j]));
        sk_vec3d o = fr->point[sk_hand_link_point(j)], b = s->bind.point[sk_hand_link_point(j)];
        sk_vec3d t = sk_v3d_sub(o, sk_m3d_apply(r, b));
        for (int i = 0; i < 3; i++) {
            mats[j][4 * i] = (float)r.m[i][0];
            mats[j][4 * i + 1] = (float)r.m[i][1];
            mats[j][4 * i + 2] = (float)r.m[i][2];
        }
        mats[j][3] = (float)t.x, mats[j][7] = (float)t.y, mats[j][11] = (float)t.z;
    }
}

/* Unit dual quaternion of each link: real part (w, x, y, z), dual part. */
static void link_dual_quaternions(float mats[SK_HAND_LINK_COUNT][12], float dq[SK_HAND_LINK_COUNT][8])
{
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        const float *m = mats[j];
        sk_mat3d r = {{{m[0], m[1], m[2]}, {m[4], m[5], m[6]}, {m[8], m[9], m[10]}}};
        sk_quatd q = sk_m3d_to_qd(r);
        sk_quatd t = sk_qd(0, m[3], m[7], m[11]);
        sk_quatd d = sk_qd_mul(t, q);
        dq[j][0] = (float)q.w, dq[j][1] = (float)q.x, dq[j][2] = (float)q.y, dq[j][3] = (float)q.z;
        dq[j][4] = (float)(0.5 * d.w), dq[j][5] = (float)(0.5 * d.x), dq[j][6] = (float)(0.5 * d.y),
        dq[j][7] = (float)(0.5 * d.z);
    }
}

static void apply(const float *m, const float *P, const float *N, size_t v, float *pos, float *nrm)
{
    float x = P[3 * v], y = P[3 * v + 1], z = P[3 * v + 2];
    pos[3 * v] = m[0] * x + m[1] * y + m[2] * z + m[3];
    pos[3 * v + 1] = m[4] * x + m[5] * y + m[6] * z + m[7];
    pos[3 * v + 2] = m[8] * x + m[9] * y + m[10] * z + m[11];
    float a = N[3 * v], b = N[3 * v + 1], c = N[3 * v + 2];
    nrm[3 * v] = m[0] * a + m[1] * b + m[2] * c;
    nrm[3 * v + 1] = m[4] * a + m[5] * b + m[6] * c;
    nrm[3 * v + 2] = m[8] * a + m[9] * b + m[10] * c;
}

static void deform_lbs(const sk_hand_surface *s, float mats[SK_HAND_LINK_COUNT][12], bool rigid, size_t lo,
                       size_t hi, float *pos, float *nrm)
{
    const float *P = s->mesh.positions, *N = s->mesh.normals;
    const uint16_t *L = s->links[rigid ? 0 : 1];
    const float *W = s->weights[rigid ? 0 : 1];
    for (size_t v = lo; v < hi; v++) {
        const uint16_t *l = L + 4 * v;
        const float *w = W + 4 * v;
        float m[12];
        int n = rigid ? 1 : s->influences[v];
        if (n == 1) {
            apply(mats[l[0]], P, N, v, pos, nrm);
            continue;
        } else {
            for (int i = 0; i < 12; i++) m[i] = w[0] * mats[l[0]][i];
            for (int k = 1; k < n; k++)
                for (int i = 0; i < 12; i++) m[i] += w[k] * mats[l[k]][i];
        }
        float x = P[3 * v], y = P[3 * v + 1], z = P[3 * v + 2];
        pos[3 * v] = m[0] * x + m[1] * y + m[2] * z + m[3];
        pos[3 * v + 1] = m[4] * x + m[5] * y + m[6] * z + m[7];
        pos[3 * v + 2] = m[8] * x + m[9] * y + m[10] * z + m[11];
        float a = N[3 * v], b = N[3 * v + 1], c = N[3 * v + 2];
        float nx = m[0] * a + m[1] * b + m[2] * c, ny = m[4] * a + m[5] * b + m[6] * c,
              nz = m[8] * a + m[9] * b + m[10] * c;
        float len2 = nx * nx + ny * ny + nz * nz;
        float inv = len2 > 0.0f ? 1.0f / sqrtf(len2) : 0.0f;
        nrm[3 * v] = nx * inv, nrm[3 * v + 1] = ny * inv, nrm[3 * v + 2] = nz * inv;
    }
}

static void deform_dqs(const sk_hand_surface *s, float mats[SK_HAND_LINK_COUNT][12], float dq[SK_HAND_LINK_COUNT][8],
                       size_t lo, size_t hi, float *pos, float *nrm)
{
    const float *P = s->mesh.positions, *N = s->mesh.normals;
    const uint16_t *L = s->links[1];
    const float *W = s->weights[1];
    for (size_t v = lo; v < hi; v++) {
        const uint16_t *l = L + 4 * v;
        const float *w = W + 4 * v;
        int n = s->influences[v];
        if (n == 1) {
            /* one link: its rigid motion, the same as the dual quaternion's */
            apply(mats[l[0]], P, N, v, pos, nrm);
            continue;
        }
        const float *q0 = dq[l[0]];
        float b[8];
        for (int i = 0; i < 8; i++) b[i] = w[0] * q0[i];
        for (int k = 1; k < n; k++) {
            const float *q = dq[l[k]];
            /* the shortest path: quaternions in the first one's hemisphere */
            float wk = q0[0] * q[0] + q0[1] * q[1] + q0[2] * q[2] + q0[3] * q[3] < 0.0f ? -w[k] : w[k];
            for (int i = 0; i < 8; i++) b[i] += wk * q[i];
        }
        float inv = 1.0f / sqrtf(b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3]);
        float qw = b[0] * inv, qx = b[1] * inv, qy = b[2] * inv, qz = b[3] * inv;
        float dw = b[4] * inv, dx = b[5] * inv, dy = b[6] * inv, dz = b[7] * inv;
        /* translation 2 d q* */
        float tx = 2.0f * (-dw * qx + dx * qw - dy * qz + dz * qy);
        float ty = 2.0f * (-dw * qy + dx * qz + dy * qw - dz * qx);
        float tz = 2.0f * (-dw * qz - dx * qy + dy * qx + dz * qw);
        float r00 = 1 - 2 * (qy * qy + qz * qz), r01 = 2 * (qx * qy - qw * qz), r02 = 2 * (qx * qz + qw * qy);
        float r10 = 2 * (qx * qy + qw * qz), r11 = 1 - 2 * (qx * qx + qz * qz), r12 = 2 * (qy * qz - qw * qx);
        float r20 = 2 * (qx * qz - qw * qy), r21 = 2 * (qy * qz + qw * qx), r22 = 1 - 2 * (qx * qx + qy * qy);
        float x = P[3 * v], y = P[3 * v + 1], z = P[3 * v + 2];
        pos[3 * v] = r00 * x + r01 * y + r02 * z + tx;
        pos[3 * v + 1] = r10 * x + r11 * y + r12 * z + ty;
        pos[3 * v + 2] = r20 * x + r21 * y + r22 * z + tz;
        float a = N[3 * v], bb = N[3 * v + 1], c = N[3 * v + 2];
        nrm[3 * v] = r00 * a + r01 * bb + r02 * c;
        nrm[3 * v + 1] = r10 * a + r11 * bb + r12 * c;
        nrm[3 * v + 2] = r20 * a + r21 * bb + r22 * c;
    }
}

#define PARALLEL_MIN_VERTICES 20000

void sk_hand_surface_deform(const sk_hand_surface *s, const sk_hand_frames *frames, sk_hand_skinning method,
                            float *positions, float *normals)
{
    float mats[SK_HAND_LINK_COUNT][12];
    link_matrices(s, frames, mats);
    size_t V = s->mesh.vertex_count;
    if (method == SK_HAND_SKINNING_DEFAULT) method = SK_HAND_SKINNING_DQS;
    float dq[SK_HAND_LINK_COUNT][8];
    if (method == SK_HAND_SKINNING_DQS) link_dual_quaternions(mats, dq);
    int chunks = V >= PARALLEL_MIN_VERTICES ? 64 : 1;
#pragma omp parallel for schedule(static) if (chunks > 1)
    for (int c = 0; c < chunks; c++) {
        size_t lo = V * (size_t)c / (size_t)chunks, hi = V * (size_t)(c + 1) / (size_t)chunks;
        if (method == SK_HAND_SKINNING_DQS) deform_dqs(s, mats, dq, lo, hi, positions, normals);
        else deform_lbs(s, mats, method == SK_HAND_SKINNING_RIGID, lo, hi, positions, normals);
    }
}

sk_result sk_hand_surface_pose(const sk_hand_surface *s, const double dofs[SK_HAND_DOF_COUNT],
                               sk_hand_skinning method, sk_mesh *out, sk_error *err)
{
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        if (!isfinite(dofs[i])) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s is not a finite number", sk_hand_dof(i)->name);
    if ((int)method < 0 || method > SK_HAND_SKINNING_DQS)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "skinning method %d is not rigid, lbs or dqs", (int)method);
    sk_result r = sk_mesh_create(out, s->mesh.vertex_count, s->mesh.triangle_count, SK_MESH_NORMALS, err);
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
