/* The layout of the 96 Bezier patches of thesis 4.1.4 ("掌、甲側の表面をそれぞれ 48 の領域に手で
 * 分割"), made automatic from the skeleton: the points of each side's scan nearest to a link
 * are split along and about the link into that link's regions; points within 0.5 mm of a
 * boundary (between two regions of a link, or between two links) belong to both regions,
 * as the thesis shares boundary data. Each region's points get the initial parameters of
 * 4.4: rows across the link 0.5 mm apart (the scan-line spacing), ordered about the link,
 * u by chord length along a row, v from the position along the link. */
#include <stdlib.h>
#include <string.h>

#include "models/hand_scan/scan_internal.h"

/* Per side: 48 regions (the thesis's count), more where the hand is larger or curvier. */
static const sk_hand_layout_entry layout[SK_HAND_LINK_COUNT] = {
    {0, 2, 2},                                     /* carpus: the heel of the hand, the wrist */
    {1, 2, 2},  {2, 2, 1},  {3, 2, 1},             /* thumb: metacarpal (thenar), phalanges */
    {4, 3, 1},  {5, 2, 1},  {6, 2, 1},  {7, 2, 1}, /* index: metacarpal, proximal, middle, distal */
    {8, 3, 1},  {9, 2, 1},  {10, 2, 1}, {11, 2, 1}, /* middle */
    {12, 3, 1}, {13, 2, 1}, {14, 2, 1}, {15, 2, 1}, /* ring */
    {16, 3, 1}, {17, 2, 1}, {18, 2, 1}, {19, 2, 1}, /* little */
};

const sk_hand_layout_entry *sk_hand_patch_layout_table(void) { return layout; }

#define MARGIN_MM 0.5
#define ROW_MM 0.5

/* Index of a link's first patch within a side. */
static int first_patch_of_link(int link)
{
    int k = 0;
    for (int l = 0; l < link; l++) k += layout[l].along * layout[l].around;
    return k;
}

typedef struct member {
    uint32_t point;
    int16_t link;
    uint8_t side;
    bool primary;
    double s, phi, radius; /* along the link (mm), angle about it, distance from its axis */
} member;

static int compare_members(const void *a, const void *b)
{
    const member *x = a, *y = b;
    int gx = x->side * SK_HAND_LINK_COUNT + x->link, gy = y->side * SK_HAND_LINK_COUNT + y->link;
    if (gx != gy) return gx < gy ? -1 : 1;
    return x->point < y->point ? -1 : (x->point > y->point);
}

typedef struct prow {
    double key; /* row, then angle */
    double phi;
    uint32_t index;
} prow;

static int compare_prow(const void *a, const void *b)
{
    const prow *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    if (x->phi != y->phi) return x->phi < y->phi ? -1 : 1;
    return x->index < y->index ? -1 : (x->index > y->index);
}

static void fill_member(const sk_hand_link_geometry *links, const sk_hand_cloud *cloud, uint32_t i,
                        int l, bool primary, member *m)
{
    m->point = i;
    m->link = (int16_t)l;
    m->side = cloud->side[i];
    m->primary = primary;
    sk__hand_link_coordinates(links, l, cloud->position[i], &m->s, &m->phi);
    sk_vec3d axis = sk_v3d_normalize(sk_v3d_sub(links->b[l], links->a[l]));
    sk_vec3d q = sk_v3d_sub(cloud->position[i], links->a[l]);
    m->radius = sk_v3d_length(sk_v3d_sub(q, sk_v3d_scale(axis, sk_v3d_dot(q, axis))));
}

/* The initial parameters of one patch's points (members[idx[k]] for k < n). */
static void initial_parameters(const sk_hand_cloud *cloud, const member *members,
                               const uint32_t *idx, size_t n, double s_lo, double s_hi,
                               double phi_lo, double phi_hi, prow *scratch, sk_vec3d *row_pts,
                               double *row_u, double *u, double *v)
{
    for (size_t k = 0; k < n; k++) {
        const member *m = &members[idx[k]];
        /* u runs against the angle, so that S_u x S_v points away from the link (the angle
           turns from the frame's X toward X x axis, so its tangent x axis points inward) */
        scratch[k] = (prow){floor((m->s - s_lo) / ROW_MM), -m->phi, (uint32_t)k};
        v[k] = sk_clampd((m->s - s_lo) / (s_hi - s_lo), 0.0, 1.0);
    }
    qsort(scratch, n, sizeof *scratch, compare_prow);
    double span = phi_hi - phi_lo;
    for (size_t a = 0; a < n;) {
        size_t b = a;
        while (b < n && scratch[b].key == scratch[a].key) b++;
        size_t len = b - a;
        for (size_t k = 0; k < len; k++)
            row_pts[k] = cloud->position[members[idx[scratch[a + k].index]].point];
        sk_hand_chord_parameters(row_pts, len, row_u);
        /* chord length along the row, 0 to 1 across it (4.4); a lone point sits where it is */
        double f0 = (phi_hi + scratch[a].phi) / span;
        for (size_t k = 0; k < len; k++)
            u[scratch[a + k].index] = len == 1 ? sk_clampd(f0, 0.0, 1.0) : row_u[k];
        a = b;
    }
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y);
}

/* The regions of one link on one side: g[0..count) are its members (primary and shared). */
static sk_result layout_group(const sk_hand_cloud *cloud, member *g, size_t count, double *phis,
                              uint32_t *idx, prow *scratch, sk_vec3d *row_pts, double *row_u,
                              sk_hand_patch_set *out, sk_error *err)
{
    int side = g[0].side, link = g[0].link;
    const sk_hand_layout_entry *e = &layout[link];
    size_t np = 0;
    double s_lo = INFINITY, s_hi = -INFINITY;
    for (size_t k = 0; k < count; k++)
        if (g[k].primary) {
            phis[np++] = g[k].phi;
            if (g[k].s < s_lo) s_lo = g[k].s;
            if (g[k].s > s_hi) s_hi = g[k].s;
        }
    if (np < 16 || !(s_hi > s_lo)) return SK_OK; /* too little data: its patches stay empty */
    /* the angular range: the circle cut at the widest gap between the primary angles */
    qsort(phis, np, sizeof *phis, compare_double);
    size_t cut = np - 1;
    double gap = phis[0] + 2.0 * SK_PI - phis[np - 1];
    for (size_t k = 0; k + 1 < np; k++)
        if (phis[k + 1] - phis[k] > gap) gap = phis[k + 1] - phis[k], cut = k;
    double phi_lo = phis[(cut + 1) % np];
    double span = 2.0 * SK_PI - gap;
    for (size_t k = 0; k < count; k++) {
        double a = phi_lo + sk_fmodpos(g[k].phi - phi_lo, 2.0 * SK_PI);
        if (a > phi_lo + span + 0.5 * gap) a -= 2.0 * SK_PI; /* just below the start */
        g[k].phi = a;
    }
    if (!(span > 0.0)) return SK_OK;
    int base = side * SK_HAND_PATCHES_PER_SIDE + first_patch_of_link(link);
    for (int a = 0; a < e->along; a++)
        for (int b = 0; b < e->around; b++) {
            double s0 = s_lo + (s_hi - s_lo) * a / e->along,
                   s1 = s_lo + (s_hi - s_lo) * (a + 1) / e->along;
            double f0 = phi_lo + span * b / e->around, f1 = phi_lo + span * (b + 1) / e->around;
            size_t n = 0;
            double ps_lo = INFINITY, ps_hi = -INFINITY, pf_lo = INFINITY, pf_hi = -INFINITY;
            for (size_t k = 0; k < count; k++) {
                double mf = MARGIN_MM / (g[k].radius > 1.0 ? g[k].radius : 1.0);
                if (g[k].s < s0 - MARGIN_MM || g[k].s > s1 + MARGIN_MM || g[k].phi < f0 - mf ||
                    g[k].phi > f1 + mf)
                    continue;
                idx[n++] = (uint32_t)k;
                ps_lo = fmin(ps_lo, g[k].s), ps_hi = fmax(ps_hi, g[k].s);
                pf_lo = fmin(pf_lo, g[k].phi), pf_hi = fmax(pf_hi, g[k].phi);
            }
            int pk = base + a * e->around + b;
            if (n < 16 || !(ps_hi > ps_lo) || !(pf_hi > pf_lo)) continue;
            sk_hand_patch_data *d = &out->data[pk];
            d->point = malloc(sizeof *d->point * n);
            d->u = malloc(sizeof *d->u * n);
            d->v = malloc(sizeof *d->v * n);
            if (!d->point || !d->u || !d->v)
                return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "patch layout");
            d->count = n;
            initial_parameters(cloud, g, idx, n, ps_lo, ps_hi, pf_lo, pf_hi, scratch, row_pts,
                               row_u, d->u, d->v);
            for (size_t k = 0; k < n; k++) d->point[k] = g[idx[k]].point;
        }
    return SK_OK;
}

sk_result sk_hand_patch_layout_build(const sk_hand_cloud *cloud, const sk_hand_link_geometry *links,
                                     sk_hand_patch_set *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (cloud->count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "patch layout: the point cloud is empty");
    if (cloud->count > (1u << 26))
        return sk_fail(err, SK_ERROR_LIMIT, "patch layout: %zu points (at most 2^26)",
                       cloud->count);
    out->count = SK_HAND_PATCH_COUNT;
    for (int side = 0; side < SK_HAND_SCAN_SIDE_COUNT; side++)
        for (int l = 0; l < SK_HAND_LINK_COUNT; l++)
            for (int a = 0; a < layout[l].along; a++)
                for (int b = 0; b < layout[l].around; b++) {
                    sk_hand_patch *p =
                        &out->patch[side * SK_HAND_PATCHES_PER_SIDE + first_patch_of_link(l) +
                                    a * layout[l].around + b];
                    p->link = l;
                    p->side = (sk_hand_scan_side)side;
                    p->along = a;
                    p->around = b;
                }
    /* every point's nearest link, and the second nearest when the point is this near the
       boundary between the two */
    size_t n = cloud->count;
    member *members = malloc(sizeof *members * 2 * n);
    if (!members) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "patch layout of %zu points", n);
    long long count = (long long)n;
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < count; i++) {
        sk_vec3d p = cloud->position[i];
        double d1 = INFINITY, d2 = INFINITY;
        int l1 = 0, l2 = -1;
        for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
            sk_vec3d ab = sk_v3d_sub(links->b[l], links->a[l]);
            double len2 = sk_v3d_dot(ab, ab);
            double t = len2 > 0
                           ? sk_clampd(sk_v3d_dot(sk_v3d_sub(p, links->a[l]), ab) / len2, 0.0, 1.0)
                           : 0.0;
            double d = sqrt(sk__dist2(p, sk_v3d_add(links->a[l], sk_v3d_scale(ab, t))));
            if (d < d1)
                d2 = d1, l2 = l1, d1 = d, l1 = l;
            else if (d < d2)
                d2 = d, l2 = l;
        }
        fill_member(links, cloud, (uint32_t)i, l1, true, &members[2 * i]);
        /* the bisector of two segments is where d1 = d2: within MARGIN_MM of it, d2 - d1 is
           below about twice the margin */
        if (l2 >= 0 && d2 - d1 < 2.0 * MARGIN_MM)
            fill_member(links, cloud, (uint32_t)i, l2, false, &members[2 * i + 1]);
        else
            members[2 * i + 1].link = -1;
    }
    size_t m = 0;
    for (size_t i = 0; i < 2 * n; i++)
        if (members[i].link >= 0) members[m++] = members[i];
    qsort(members, m, sizeof *members, compare_members);
    sk_result r = SK_OK;
    double *phis = malloc(sizeof *phis * (m ? m : 1));
    uint32_t *idx = malloc(sizeof *idx * (m ? m : 1));
    prow *scratch = malloc(sizeof *scratch * (m ? m : 1));
    sk_vec3d *row_pts = malloc(sizeof *row_pts * (m ? m : 1));
    double *row_u = malloc(sizeof *row_u * (m ? m : 1));
    if (!phis || !idx || !scratch || !row_pts || !row_u)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "patch layout");
    for (size_t g0 = 0; g0 < m && r == SK_OK;) {
        size_t g1 = g0;
        while (g1 < m && members[g1].side == members[g0].side &&
               members[g1].link == members[g0].link)
            g1++;
        r = layout_group(cloud, members + g0, g1 - g0, phis, idx, scratch, row_pts, row_u, out,
                         err);
        g0 = g1;
    }
    free(phis), free(idx), free(scratch), free(row_pts), free(row_u);
    free(members);
    if (r != SK_OK) sk_hand_patch_set_free(out);
    return r;
}

void sk_hand_patch_set_free(sk_hand_patch_set *set)
{
    for (int k = 0; k < SK_HAND_PATCH_COUNT; k++) {
        free(set->data[k].point);
        free(set->data[k].u);
        free(set->data[k].v);
        free(set->error_scan[k]);
        free(set->error_truth[k]);
    }
    memset(set, 0, sizeof *set);
}
