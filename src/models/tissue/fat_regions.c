/* Where fat lies (the character file's per-region thickness; the paper gives the fat no
 * shape of its own): grid points near the tissue beside a named bone or muscle, between
 * two places along it and on one side of it, are made fat before the dilations of sec. 4,
 * so the skin passes outside them. */
#include <math.h>
#include <stdlib.h>

#include "models/tissue/tissue_internal.h"

typedef struct region {
    sk_vec3d a, u; /* axis start and unit direction (rest world) */
    double length;
    double from, to; /* along the axis, fractions */
    double thickness;
    sk_vec3d side;    /* unit direction of the side, or zero for all around */
    bool side_across; /* side measured across the axis (else from the region centre) */
    double cos_spread;
    sk_vec3d lo, hi; /* bounds of the candidates */
} region;

static void make_region(const sk_tissue_fat_desc *f, const sk_tissue_character_desc *d,
                        const sk__skeleton *s, const sk__bone *bones, const sk__muscle *muscles,
                        region *r)
{
    sk_vec3d a, b;
    double reach;
    int bi = sk__bone_find(d, f->around);
    if (bi >= 0) {
        const sk__bone *bone = &bones[bi];
        a = sk_v3d_add(s->rest[bone->joint], bone->start);
        b = sk_v3d_add(s->rest[bone->joint], bone->end);
        reach = bone->bound_radius;
    } else {
        const sk__muscle *m = &muscles[sk__muscle_find(d, f->around)];
        a = sk_v3d_add(s->rest[m->origin_joint], m->origin);
        b = sk_v3d_add(s->rest[m->insertion_joint], m->insertion);
        reach = fmax(m->a0, fmax(m->b0, m->c0)) * 2.0; /* the belly may bulge */
    }
    r->a = a;
    r->length = sk_v3d_length(sk_v3d_sub(b, a));
    r->u = sk_v3d_normalize(sk_v3d_sub(b, a));
    r->from = f->from;
    r->to = f->to;
    r->thickness = f->thickness_mm;
    sk_vec3d dir = sk_v3d_normalize(sk_v3d(f->direction[0], f->direction[1], f->direction[2]));
    sk_vec3d across = sk_v3d_sub(dir, sk_v3d_scale(r->u, sk_v3d_dot(dir, r->u)));
    r->side_across = sk_v3d_length(across) > 1e-6;
    r->side = r->side_across ? sk_v3d_normalize(across) : dir;
    r->cos_spread = cos(f->spread_deg * SK_DEG_TO_RAD);
    sk_vec3d p0 = sk_v3d_add(a, sk_v3d_scale(r->u, r->from * r->length));
    sk_vec3d p1 = sk_v3d_add(a, sk_v3d_scale(r->u, r->to * r->length));
    double grow = reach + r->thickness;
    r->lo = sk_v3d(fmin(p0.x, p1.x) - grow, fmin(p0.y, p1.y) - grow, fmin(p0.z, p1.z) - grow);
    r->hi = sk_v3d(fmax(p0.x, p1.x) + grow, fmax(p0.y, p1.y) + grow, fmax(p0.z, p1.z) + grow);
}

static bool in_region(const region *r, sk_vec3d p)
{
    sk_vec3d ap = sk_v3d_sub(p, r->a);
    double along = sk_v3d_dot(ap, r->u);
    double t = along / r->length;
    if (t < r->from || t > r->to) return false;
    if (sk_v3d_length(r->side) == 0.0 || r->cos_spread <= -1.0) return true;
    sk_vec3d v = r->side_across
                     ? sk_v3d_sub(ap, sk_v3d_scale(r->u, along))
                     : sk_v3d_sub(ap, sk_v3d_scale(r->u, 0.5 * (r->from + r->to) * r->length));
    double len = sk_v3d_length(v);
    return len > 0.0 && sk_v3d_dot(v, r->side) >= r->cos_spread * len;
}

sk_result sk__fat_regions_mark(const sk_tissue_character_desc *d, const sk__skeleton *s,
                               const sk__bone *bones, const sk__muscle *muscles, const sk__grid *g,
                               const sk__label *labels, uint8_t *fat, sk_error *err)
{
    for (int k = 0; k < d->fat_count; k++) {
        region r;
        make_region(&d->fat[k], d, s, bones, muscles, &r);
        int lo[3], hi[3], blo[3], bhi[3];
        double l[3] = {r.lo.x, r.lo.y, r.lo.z}, h[3] = {r.hi.x, r.hi.y, r.hi.z};
        double o[3] = {g->origin.x, g->origin.y, g->origin.z};
        /* the distance is needed up to the thickness: the box around the region, grown by
           it, holds all the tissue that near */
        int grow = (int)ceil(r.thickness / g->spacing) + 1;
        for (int a = 0; a < 3; a++) {
            lo[a] = (int)ceil((l[a] - o[a]) / g->spacing);
            hi[a] = (int)floor((h[a] - o[a]) / g->spacing);
            if (lo[a] < 0) lo[a] = 0;
            if (hi[a] > g->n[a] - 1) hi[a] = g->n[a] - 1;
            blo[a] = lo[a] - grow < 0 ? 0 : lo[a] - grow;
            bhi[a] = hi[a] + grow > g->n[a] - 1 ? g->n[a] - 1 : hi[a] + grow;
        }
        if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) continue;
        int bn[3] = {bhi[0] - blo[0] + 1, bhi[1] - blo[1] + 1, bhi[2] - blo[2] + 1};
        float *distance = malloc((size_t)bn[0] * (size_t)bn[1] * (size_t)bn[2] * sizeof *distance);
        if (!distance) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for fat[%d]", k);
        sk_result res = sk__distance_to_tissue(g, labels, blo, bhi, distance, err);
        if (res != SK_OK) {
            free(distance);
            return res;
        }
#pragma omp parallel for schedule(dynamic, 2)
        for (int z = lo[2]; z <= hi[2]; z++)
            for (int y = lo[1]; y <= hi[1]; y++)
                for (int x = lo[0]; x <= hi[0]; x++) {
                    size_t i = sk__grid_index(g, x, y, z);
                    float dist =
                        distance[((size_t)(z - blo[2]) * (size_t)bn[1] + (size_t)(y - blo[1])) *
                                     (size_t)bn[0] +
                                 (size_t)(x - blo[0])];
                    if (fat[i] || dist <= 0.0f || dist > r.thickness) continue;
                    if (in_region(&r, sk__grid_position(g, i))) fat[i] = 1;
                }
        free(distance);
    }
    return SK_OK;
}
