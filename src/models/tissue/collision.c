/* No skin point inside a bone (spec/tissue.md: collisions with the tissue are not asked
 * for, but no skin point may end inside bone): after the springs, every fat and skin point
 * found inside one of a bone's three ellipsoids is moved out along the ray from the
 * ellipsoid's centre to its surface. The muscles are kept out of the same way (beyond the
 * paper: without it, a fast motion can press fat points through the layer of muscle points
 * and leave them tangled inside the muscle). Points are tested in blocks of consecutive
 * points (neighbours on the grid): a block's bounds select the obstacles worth testing,
 * a point's position the ellipsoids. */
#include <float.h>
#include <math.h>
#include <stdint.h>

#include "models/tissue/sim_internal.h"
#include "models/tissue/simd.h"

#define BLOCK 64 /* at most 64: a block's points are the bits of a mask */
_Static_assert(BLOCK <= 64, "a block's points must fit a 64-bit mask");
#define MARGIN 1e-6                              /* in level units: just outside the surface */
#define INSIDE ((1.0 + MARGIN) * (1.0 + MARGIN)) /* a level below this is inside */

static void part_setup(sk__obstacle_part *q, const sk__ellipsoid *e)
{
    q->e = *e;
    for (int r = 0; r < 3; r++) {
        double inv = 1.0 / (r == 0 ? e->radii.x : (r == 1 ? e->radii.y : e->radii.z));
        for (int c = 0; c < 3; c++)
            q->to_unit[r][c] = e->axes.m[c][r] * inv; /* row r: axis r / radius r */
    }
    sk__ellipsoid_bounds(e, &q->lo, &q->hi);
}

static void bounds_of_parts(sk__obstacle *o)
{
    o->lo = o->part[0].lo;
    o->hi = o->part[0].hi;
    for (int k = 1; k < o->parts; k++) {
        const sk__obstacle_part *q = &o->part[k];
        o->lo = sk_v3d(q->lo.x < o->lo.x ? q->lo.x : o->lo.x, q->lo.y < o->lo.y ? q->lo.y : o->lo.y,
                       q->lo.z < o->lo.z ? q->lo.z : o->lo.z);
        o->hi = sk_v3d(q->hi.x > o->hi.x ? q->hi.x : o->hi.x, q->hi.y > o->hi.y ? q->hi.y : o->hi.y,
                       q->hi.z > o->hi.z ? q->hi.z : o->hi.z);
    }
}

int sk__obstacles(const sk_tissue_model *m, const sk_tissue_pose *pose,
                  const sk__muscle_state *muscle, sk__obstacle *out)
{
    int n = 0;
    for (int b = 0; b < m->desc.bone_count; b++, n++) {
        const sk__bone *bone = &m->bones[b];
        sk_mat3d r = sk_qd_to_m3d(pose->rotation[bone->joint]);
        sk_vec3d t = pose->position[bone->joint];
        out[n].parts = 3;
        for (int k = 0; k < 3; k++) {
            sk__ellipsoid e = sk__ellipsoid_transform(&bone->part[k], r, t);
            part_setup(&out[n].part[k], &e);
        }
        bounds_of_parts(&out[n]);
    }
    for (int i = 0; i < m->desc.muscle_count; i++, n++) {
        out[n].parts = 1;
        part_setup(&out[n].part[0], &muscle[i].body);
        bounds_of_parts(&out[n]);
    }
    return n;
}

/* (The comparisons joined without branches: where a point lies is hard to predict.) */
static bool in_box(const double *p, sk_vec3d lo, sk_vec3d hi)
{
    return (p[0] >= lo.x) & (p[0] <= hi.x) & (p[1] >= lo.y) & (p[1] <= hi.y) & (p[2] >= lo.z) &
           (p[2] <= hi.z);
}

static double level(const sk__obstacle_part *q, const double *p)
{
    double d[3] = {p[0] - q->e.centre.x, p[1] - q->e.centre.y, p[2] - q->e.centre.z}, s = 0.0;
    for (int r = 0; r < 3; r++) {
        double u = q->to_unit[r][0] * d[0] + q->to_unit[r][1] * d[1] + q->to_unit[r][2] * d[2];
        s += u * u;
    }
    return s;
}

/* Moves x out of the obstacle's ellipsoids it is in; returns whether it moved. */
static bool push_out(const sk__obstacle *o, double *x)
{
    bool moved = false;
    for (int k = 0; k < o->parts; k++) {
        const sk__obstacle_part *q = &o->part[k];
        if (!in_box(x, q->lo, q->hi) || level(q, x) >= INSIDE) continue;
        sk_vec3d p = sk_v3d(x[0], x[1], x[2]);
        sk__ellipsoid_push_out(&q->e, &p, MARGIN);
        x[0] = p.x;
        x[1] = p.y;
        x[2] = p.z;
        moved = true;
    }
    return moved;
}

/* Bounds of points p0..p1 of x. */
static void block_bounds(const double *x, size_t p0, size_t p1, double lo[3], double hi[3])
{
    double lx = DBL_MAX, ly = DBL_MAX, lz = DBL_MAX, hx = -DBL_MAX, hy = -DBL_MAX, hz = -DBL_MAX;
    for (size_t p = p0; p < p1; p++) {
        double vx = x[3 * p], vy = x[3 * p + 1], vz = x[3 * p + 2];
        lx = vx < lx ? vx : lx, ly = vy < ly ? vy : ly, lz = vz < lz ? vz : lz;
        hx = vx > hx ? vx : hx, hy = vy > hy ? vy : hy, hz = vz > hz ? vz : hz;
    }
    lo[0] = lx, lo[1] = ly, lo[2] = lz;
    hi[0] = hx, hi[1] = hy, hi[2] = hz;
}

/* The obstacles of one kind (muscles: parts == 1, bones: parts == 3) whose bounds meet
 * the box; returns how many were written to `out`. */
static int near_block(const sk__obstacle *obstacles, int count, int parts, const double lo[3],
                      const double hi[3], int *out)
{
    int n = 0;
    for (int b = 0; b < count; b++) {
        const sk__obstacle *o = &obstacles[b];
        if (o->parts != parts || o->lo.x > hi[0] || o->hi.x < lo[0] || o->lo.y > hi[1] ||
            o->hi.y < lo[1] || o->lo.z > hi[2] || o->hi.z < lo[2])
            continue;
        out[n++] = b;
    }
    return n;
}

/* The points of p0..p1 (as bits from p0) that lie inside an ellipsoid of one of the `n`
 * obstacles `near` (muscles: only those set in the point's near_muscles mask, else
 * bones): the only ones a pass can move, since a point inside none is left as it is.
 * Four points at a time in AVX2 lanes with in_box's and level's operations; without AVX2
 * every point is a candidate (`vectors` false: the same, for the tests). */
#if defined(SK__HAVE_AVX2_PATH)
static inline SK__AVX2 __m256d box_lanes(__m256d x, __m256d y, __m256d z, const sk_vec3d *lo,
                                         const sk_vec3d *hi)
{
    __m256d in = _mm256_and_pd(_mm256_cmp_pd(x, _mm256_broadcast_sd(&lo->x), _CMP_GE_OQ),
                               _mm256_cmp_pd(x, _mm256_broadcast_sd(&hi->x), _CMP_LE_OQ));
    in =
        _mm256_and_pd(in, _mm256_and_pd(_mm256_cmp_pd(y, _mm256_broadcast_sd(&lo->y), _CMP_GE_OQ),
                                        _mm256_cmp_pd(y, _mm256_broadcast_sd(&hi->y), _CMP_LE_OQ)));
    return _mm256_and_pd(in,
                         _mm256_and_pd(_mm256_cmp_pd(z, _mm256_broadcast_sd(&lo->z), _CMP_GE_OQ),
                                       _mm256_cmp_pd(z, _mm256_broadcast_sd(&hi->z), _CMP_LE_OQ)));
}

/* level() in the lanes, compared: !(level >= INSIDE). */
static inline SK__AVX2 __m256d inside_lanes(const sk__obstacle_part *q, __m256d x, __m256d y,
                                            __m256d z)
{
    __m256d d0 = _mm256_sub_pd(x, _mm256_broadcast_sd(&q->e.centre.x));
    __m256d d1 = _mm256_sub_pd(y, _mm256_broadcast_sd(&q->e.centre.y));
    __m256d d2 = _mm256_sub_pd(z, _mm256_broadcast_sd(&q->e.centre.z));
    __m256d s = _mm256_setzero_pd();
    for (int r = 0; r < 3; r++) {
        __m256d u =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_broadcast_sd(&q->to_unit[r][0]), d0),
                                        _mm256_mul_pd(_mm256_broadcast_sd(&q->to_unit[r][1]), d1)),
                          _mm256_mul_pd(_mm256_broadcast_sd(&q->to_unit[r][2]), d2));
        s = _mm256_add_pd(s, _mm256_mul_pd(u, u));
    }
    return _mm256_and_pd(box_lanes(x, y, z, &q->lo, &q->hi),
                         _mm256_cmp_pd(s, _mm256_set1_pd(INSIDE), _CMP_NGE_UQ));
}

static SK__AVX2 uint64_t candidates_wide(const sk__obstacle *obstacles, const int *near, int n,
                                         int bone_count, const uint64_t *near_muscles,
                                         const double *x, size_t p0, size_t p1)
{
    uint64_t mask = 0;
    size_t p = p0;
    for (; p + 4 <= p1; p += 4) {
        const double *q = x + 3 * p;
        __m256d px = _mm256_setr_pd(q[0], q[3], q[6], q[9]),
                py = _mm256_setr_pd(q[1], q[4], q[7], q[10]),
                pz = _mm256_setr_pd(q[2], q[5], q[8], q[11]);
        __m256d any = _mm256_setzero_pd();
        for (int k = 0; k < n; k++) {
            const sk__obstacle *o = &obstacles[near[k]];
            __m256d in = box_lanes(px, py, pz, &o->lo, &o->hi);
            if (near_muscles) {
                int bit = near[k] - bone_count;
                __m256i allowed = _mm256_setr_epi64x(-(long long)(near_muscles[p] >> bit & 1),
                                                     -(long long)(near_muscles[p + 1] >> bit & 1),
                                                     -(long long)(near_muscles[p + 2] >> bit & 1),
                                                     -(long long)(near_muscles[p + 3] >> bit & 1));
                in = _mm256_and_pd(in, _mm256_castsi256_pd(allowed));
            }
            if (_mm256_movemask_pd(in) == 0) continue;
            for (int j = 0; j < o->parts; j++)
                any = _mm256_or_pd(any, _mm256_and_pd(in, inside_lanes(&o->part[j], px, py, pz)));
        }
        mask |= (uint64_t)_mm256_movemask_pd(any) << (p - p0);
    }
    for (; p < p1; p++) mask |= (uint64_t)1 << (p - p0);
    return mask;
}
#endif

static uint64_t candidates(const sk__obstacle *obstacles, const int *near, int n, int bone_count,
                           const uint64_t *near_muscles, const double *x, size_t p0, size_t p1,
                           bool vectors)
{
#if defined(SK__HAVE_AVX2_PATH)
    if (vectors) return candidates_wide(obstacles, near, n, bone_count, near_muscles, x, p0, p1);
#endif
    (void)obstacles, (void)near, (void)n, (void)bone_count, (void)near_muscles, (void)x,
        (void)vectors;
    return p1 - p0 < 64 ? ((uint64_t)1 << (p1 - p0)) - 1 : ~(uint64_t)0;
}

/* The collisions of the points of one block. */
static void collide_block(const sk__obstacle *obstacles, int obstacle_count, int bone_count,
                          const uint64_t *near_muscles, double *x, size_t p0, size_t p1,
                          bool vectors)
{
    double lo[3], hi[3];
    int near[SK__MAX_OBSTACLES];
    block_bounds(x, p0, p1, lo, hi);
    /* muscles first, bones last: no point may end in a bone */
    int n = near_block(obstacles, obstacle_count, 1, lo, hi, near);
    bool moved = false;
    uint64_t test =
        n ? candidates(obstacles, near, n, bone_count, near_muscles, x, p0, p1, vectors) : 0;
    for (size_t p = p0; p < p1; p++)
        for (int k = 0; k < n && (test >> (p - p0) & 1); k++)
            if ((near_muscles[p] >> (near[k] - bone_count) & 1) &&
                in_box(x + 3 * p, obstacles[near[k]].lo, obstacles[near[k]].hi))
                moved |= push_out(&obstacles[near[k]], x + 3 * p);
    /* bones overlap at the joints: out of one may be into the next, so repeat (with
       the bones near where the points now are) for the points that moved: a point that
       did not is outside every bone near it, and every bone that could hold it is near */
    uint64_t again = ~(uint64_t)0; /* points of the block to test (BLOCK = 64) */
    for (int pass = 0; pass < 8 && again; pass++) {
        if (moved) block_bounds(x, p0, p1, lo, hi); /* else still those of the points */
        n = near_block(obstacles, obstacle_count, 3, lo, hi, near);
        if (pass == 0)
            again = n ? candidates(obstacles, near, n, bone_count, NULL, x, p0, p1, vectors) : 0;
        moved = false;
        uint64_t next = 0;
        for (size_t p = p0; p < p1; p++) {
            if (!(again >> (p - p0) & 1)) continue;
            bool out = false;
            for (int k = 0; k < n; k++)
                if (in_box(x + 3 * p, obstacles[near[k]].lo, obstacles[near[k]].hi))
                    out |= push_out(&obstacles[near[k]], x + 3 * p);
            if (out) next |= (uint64_t)1 << (p - p0);
        }
        moved = next != 0;
        again = next;
    }
}

void sk__collide(const sk__obstacle *obstacles, int obstacle_count, int bone_count,
                 const uint64_t *near_muscles, double *x, size_t count, bool vectors)
{
    size_t blocks = (count + BLOCK - 1) / BLOCK;
#pragma omp for schedule(dynamic, 16)
    for (size_t blk = 0; blk < blocks; blk++) {
        size_t p0 = blk * BLOCK, p1 = p0 + BLOCK < count ? p0 + BLOCK : count;
        collide_block(obstacles, obstacle_count, bone_count, near_muscles, x, p0, p1, vectors);
    }
}

void sk__collide_finish(const sk__obstacle *obstacles, int obstacle_count, int bone_count,
                        const uint64_t *near_muscles, double *x, const double *base, double *v,
                        double inv_h, size_t count, bool vectors)
{
    size_t blocks = (count + BLOCK - 1) / BLOCK;
#pragma omp for schedule(dynamic, 16)
    for (size_t blk = 0; blk < blocks; blk++) {
        size_t p0 = blk * BLOCK, p1 = p0 + BLOCK < count ? p0 + BLOCK : count;
        if (obstacle_count > 0)
            collide_block(obstacles, obstacle_count, bone_count, near_muscles, x, p0, p1, vectors);
        for (size_t i = 3 * p0; i < 3 * p1; i++) v[i] = (x[i] - base[i]) * inv_h;
    }
}
