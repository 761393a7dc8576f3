/* Polygons from the segmented slices, thesis 4.1.3: per slice and link, the points in
 * polar coordinates about the link, resampled at evenly spaced angles (eq. 4.1) by linear
 * interpolation of the radius between the neighbouring data points (eq. 4.2), 10 points
 * each, joined to the same link's points on the next slice, a finger's tube to the palm's
 * strips over its metacarpal, and neighbouring palm strips to each other where they meet
 * (one surface, as the thesis's polygon model, Fig. 4.7).
 *
 * Eq. (4.1) spaces theta*_i = theta_min + (theta_max - theta_min) i / 10, i = 0..9: the
 * step of a closed ring, whose last interval runs back to theta_min; so a ring (a phalanx
 * fully surrounded by its own points) keeps it, and an open arc (a palm link between its
 * neighbours' points) is sampled with 9 intervals so that both of its ends are vertices.
 *
 * The thesis saw "wrinkles" because each slice was resampled alone, and proposed using
 * the neighbouring slices. SK_HAND_RESAMPLE_NEIGHBOURS places the samples consistently
 * from slice to slice: a ring's sample angles are fixed per link (theta_ref + 2 pi i / n),
 * so consecutive rings no longer twist against each other as theta_min wanders with the
 * data, and an arc's ends are averaged 1:2:1 with the matching arcs of the slices before
 * and after. The radius at each angle stays eq. (4.2) on the slice's own data: averaging
 * radii across slices as well would pull the vertices off the surface where it changes
 * along the link (joints, tips, the oblique thumb) more than it removes noise. */
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "models/hand_scan/scan_internal.h"

typedef struct segment {
    int group; /* what joins across slices: a link, or a finger's phalanges */
    int link;  /* the link whose frame fixes a ring's sample angles */
    bool ring;
    int first, count; /* into the slice's unwrapped theta / r arrays */
    double theta_min, theta_max;
    sk_vec3d centre; /* polar centre in the slice plane */
    int vertex;      /* first resampled vertex */
} segment;

typedef struct slice_work {
    int segment_count;
    segment *segments;
    double *theta, *r; /* per point, grouped by segment, theta increasing (unwrapped) */
} slice_work;

typedef struct polar {
    double theta, r;
} polar;

static int compare_polar(const void *a, const void *b)
{
    const polar *x = a, *y = b;
    if (x->theta != y->theta) return x->theta < y->theta ? -1 : 1;
    return x->r < y->r ? -1 : (x->r > y->r);
}

/* Splits a group's points (sorted by angle in (-pi, pi]) into a ring or arcs. */
static int make_segments(const polar *p, int n, int group, int link, sk_vec3d centre, bool phalanx,
                         double arc_gap, slice_work *w, int *used, segment *out)
{
    if (n < 2) return 0;
    int largest = n - 1;
    double largest_gap = p[0].theta + 2.0 * SK_PI - p[n - 1].theta;
    for (int k = 0; k + 1 < n; k++)
        if (p[k + 1].theta - p[k].theta > largest_gap)
            largest_gap = p[k + 1].theta - p[k].theta, largest = k;
    int start = (largest + 1) % n;
    double *th = w->theta + *used, *rr = w->r + *used;
    for (int j = 0; j < n; j++) {
        int k = (start + j) % n;
        th[j] = p[k].theta + (start + j >= n ? 2.0 * SK_PI : 0.0);
        rr[j] = p[k].r;
    }
    int count = 0;
    bool ring = n >= 3 && (largest_gap <= arc_gap || (phalanx && largest_gap < SK_PI));
    if (ring) {
        out[count++] = (segment){group, link, true, *used, n, th[0], th[n - 1], centre, 0};
    } else {
        int a = 0;
        for (int j = 1; j <= n; j++) {
            if (j < n && th[j] - th[j - 1] <= arc_gap) continue;
            if (j - a >= 2)
                out[count++] =
                    (segment){group, link, false, *used + a, j - a, th[a], th[j - 1], centre, 0};
            a = j;
        }
    }
    *used += n;
    return count;
}

/* The resampling groups of one slice: each palm link alone; a finger's phalanges together
 * (at a joint a slice's points fall to two links of the finger: resampled as one ring
 * about the link holding most of them, a finger is one tube from its base to its tip). */
static void slice_segments(const sk_hand_slices *slices, int s, double arc_gap, polar *scratch,
                           slice_work *w)
{
    size_t a = slices->first[s], b = slices->first[s + 1];
    int used = 0;
    int per_link[SK_HAND_LINK_COUNT] = {0};
    for (size_t k = a; k < b; k++) per_link[slices->points[k].link]++;
    bool done[SK_HAND_LINK_COUNT] = {false};
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
        if (done[l] || per_link[l] == 0) continue;
        bool phalanx = sk__hand_link_is_phalanx(l);
        int group = l, rep = l;
        bool member[SK_HAND_LINK_COUNT] = {false};
        member[l] = true;
        if (phalanx) {
            /* the finger's phalanges; the one with most points gives the centre */
            int finger = sk__hand_finger_of_link(l);
            group = SK_HAND_LINK_COUNT + finger;
            for (int o = l + 1; o < SK_HAND_LINK_COUNT; o++) {
                if (!sk__hand_link_is_phalanx(o) || sk__hand_finger_of_link(o) != finger) continue;
                member[o] = true;
                if (per_link[o] > per_link[rep]) rep = o;
            }
        }
        sk_vec3d c = slices->centre[s][rep];
        int n = 0;
        for (size_t k = a; k < b; k++) {
            const sk_hand_slice_point *p = &slices->points[k];
            if (!member[p->link]) continue;
            sk_vec3d own = slices->centre[s][p->link];
            double x = own.x + p->r * cos(p->theta) - c.x, z = own.z + p->r * sin(p->theta) - c.z;
            scratch[n++] = (polar){atan2(z, x), hypot(x, z)};
        }
        for (int o = 0; o < SK_HAND_LINK_COUNT; o++) done[o] = done[o] || member[o];
        if (phalanx) qsort(scratch, (size_t)n, sizeof *scratch, compare_polar);
        w->segment_count += make_segments(scratch, n, group, rep, c, phalanx, arc_gap, w, &used,
                                          w->segments + w->segment_count);
    }
}

/* Eq. (4.2) on a segment: the radius at angle t by linear interpolation between the
 * data points either side (across the closing gap of a ring; clamped at an arc's ends). */
static double radius_at(const slice_work *w, const segment *s, double t)
{
    const double *th = w->theta + s->first, *r = w->r + s->first;
    int n = s->count;
    if (s->ring) {
        while (t < th[0]) t += 2.0 * SK_PI;
        while (t >= th[0] + 2.0 * SK_PI) t -= 2.0 * SK_PI;
        if (t >= th[n - 1]) {
            double gap = th[0] + 2.0 * SK_PI - th[n - 1];
            return gap > 0 ? r[n - 1] + (r[0] - r[n - 1]) * (t - th[n - 1]) / gap : r[0];
        }
    } else {
        if (t <= th[0]) return r[0];
        if (t >= th[n - 1]) return r[n - 1];
    }
    int lo = 0, hi = n - 1; /* th[lo] <= t < th[hi] */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (th[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    double span = th[hi] - th[lo];
    return span > 0 ? r[lo] + (r[hi] - r[lo]) * (t - th[lo]) / span : r[lo];
}

/* Shift (a multiple of 2 pi) bringing b's interval nearest a's, and their overlap. */
static double arc_overlap(const segment *a, const segment *b, double *shift)
{
    double best = -INFINITY;
    for (int k = -1; k <= 1; k++) {
        double s = 2.0 * SK_PI * k;
        double lo = a->theta_min > b->theta_min + s ? a->theta_min : b->theta_min + s;
        double hi = a->theta_max < b->theta_max + s ? a->theta_max : b->theta_max + s;
        if (hi - lo > best) best = hi - lo, *shift = s;
    }
    return best;
}

/* The segment of a's group in slice w: its ring, or the arc overlapping `a` most (at least
 * 30 % of the shorter). */
static const segment *matching_arc(const slice_work *w, const segment *a, double *shift)
{
    const segment *best = NULL;
    double best_overlap = 0.0;
    for (int k = 0; k < w->segment_count; k++) {
        const segment *b = &w->segments[k];
        if (b->group != a->group || b->ring != a->ring) continue;
        double s = 0.0, o = b->ring ? INFINITY : arc_overlap(a, b, &s);
        double shorter = fmin(a->theta_max - a->theta_min, b->theta_max - b->theta_min);
        if (o > 0.3 * shorter && o > best_overlap) best_overlap = o, best = b, *shift = s;
    }
    return best;
}

/* Angles of the n samples of a segment (eq. 4.1, or the neighbours' version). */
static void sample_angles(const slice_work *work, int s, int count, const segment *seg,
                          sk_hand_resample_mode mode, double theta_ref, int n, double *out)
{
    if (seg->ring) {
        if (mode == SK_HAND_RESAMPLE_THESIS) {
            for (int i = 0; i < n; i++)
                out[i] = seg->theta_min + (seg->theta_max - seg->theta_min) * i / n;
        } else {
            for (int i = 0; i < n; i++) out[i] = theta_ref + 2.0 * SK_PI * i / n;
        }
        return;
    }
    double lo = seg->theta_min, hi = seg->theta_max;
    if (mode != SK_HAND_RESAMPLE_THESIS) {
        /* ends averaged 1:2:1 with the matching arcs of the slices either side */
        double wsum = 2.0, slo = 2.0 * lo, shi = 2.0 * hi;
        for (int ds = -1; ds <= 1; ds += 2) {
            int t = s + ds;
            if (t < 0 || t >= count) continue;
            double shift = 0;
            const segment *m = matching_arc(&work[t], seg, &shift);
            if (!m) continue;
            slo += m->theta_min + shift;
            shi += m->theta_max + shift;
            wsum += 1.0;
        }
        lo = slo / wsum, hi = shi / wsum;
    }
    for (int i = 0; i < n; i++) out[i] = lo + (hi - lo) * i / (n - 1);
}

static double theta_reference(const sk_hand_link_geometry *links, int l)
{
    /* the link frame's X axis seen in the slice plane (x, z) */
    return atan2(links->frame[l].m[2][0], links->frame[l].m[0][0]);
}

/* Fold angle (degrees) between triangles (a, b, c) and (c, b, d) sharing edge b-c. */
static double fold_deg(sk_vec3d a, sk_vec3d b, sk_vec3d c, sk_vec3d d)
{
    sk_vec3d n1 = sk_v3d_normalize(sk_v3d_cross(sk_v3d_sub(b, a), sk_v3d_sub(c, a)));
    sk_vec3d n2 = sk_v3d_normalize(sk_v3d_cross(sk_v3d_sub(b, c), sk_v3d_sub(d, c)));
    double cs = sk_v3d_dot(n1, n2);
    cs = cs > 1 ? 1 : (cs < -1 ? -1 : cs);
    return acos(cs) * SK_RAD_TO_DEG;
}

/* Whether a ring and arcs join across slices: the same group (where a link's points change
 * from surrounding it to lying on its sides), or one finger's metacarpal and phalanges
 * (where the palm's strips over a metacarpal end and the finger's tube begins), so that a
 * finger and the palm over its metacarpal are one surface, as the hand is. */
static bool joins(const segment *a, const segment *b)
{
    if (a->ring == b->ring) return false;
    if (a->group == b->group) return true;
    int f = sk__hand_finger_of_link(a->link);
    return f >= 0 && f == sk__hand_finger_of_link(b->link);
}

/* The segments of slice s + 1 that `seg` (slice s) joins to: its match of the same kind,
 * else the rings or arcs it joins (above), each of those. Returns how many (<= max). */
static int partners(const slice_work *next, const segment *seg, const segment **out, int max)
{
    double shift;
    const segment *m = matching_arc(next, seg, &shift);
    if (m) {
        out[0] = m;
        return 1;
    }
    int n = 0;
    for (int k = 0; k < next->segment_count && n < max; k++) {
        const segment *b = &next->segments[k];
        if (joins(seg, b) && (seg->ring || n == 0)) out[n++] = b;
    }
    return n;
}

/* The vertices of `ring` whose angles lie within half a step of the arc's range, in order
 * of angle (brought next to the arc's). Two arcs are at least arc_gap_deg apart, wider
 * than a step (360 / n deg) at the defaults, so they never share a ring edge. */
static int ring_portion(const segment *ring, const segment *arc, const double *angle, int n,
                        uint32_t *out_v, double *out_a)
{
    double lo = angle[arc->vertex], hi = angle[arc->vertex + n - 1], c = 0.5 * (lo + hi),
           step = SK_PI / n;
    int m = 0;
    for (int i = 0; i < n; i++) {
        double a = c + sk__hand_wrap_angle(angle[ring->vertex + i] - c);
        if (a < lo - step || a > hi + step) continue;
        int j = m++;
        while (j > 0 && out_a[j - 1] > a) out_a[j] = out_a[j - 1], out_v[j] = out_v[j - 1], j--;
        out_a[j] = a;
        out_v[j] = (uint32_t)(ring->vertex + i);
    }
    return m;
}

/* Triangles between two rows of vertices in order of angle, slice s (a) and s + 1 (b),
 * advancing along whichever row's next vertex comes first: p + q - 2 triangles, wound as
 * the ring-to-ring joins. */
static size_t zipper(const uint32_t *a, const double *aa, int p, const uint32_t *b,
                     const double *ba, int q, uint32_t *ix)
{
    size_t t = 0;
    int i = 0, j = 0;
    while (i < p - 1 || j < q - 1) {
        bool along_a = j == q - 1 || (i < p - 1 && aa[i + 1] <= ba[j + 1]);
        uint32_t *tri = ix + 3 * t++;
        tri[0] = a[i], tri[1] = b[j];
        tri[2] = along_a ? a[++i] : b[++j];
    }
    return t;
}

static double vertex_distance(const float *P, int a, int b)
{
    const float *p = P + 3 * (size_t)a, *q = P + 3 * (size_t)b;
    return sqrt((double)(p[0] - q[0]) * (p[0] - q[0]) + (double)(p[1] - q[1]) * (p[1] - q[1]) +
                (double)(p[2] - q[2]) * (p[2] - q[2]));
}

/* Where the palm's strips of two links meet (the metacarpals side by side), an arc's last
 * vertex lies next to another link's arc's first one: the two strips are bridged by a
 * quad between them on each pair of slices where both continue, so the palm is one
 * surface and not a strip per link (the thesis's mesh, Fig. 4.7). An end takes the other
 * link's nearest start within one sample spacing of its own arc, and only if that start
 * takes it back (never two bridges on one edge). Wound as the strips. */
static size_t bridge_strips(const slice_work *w, const slice_work *next, int n, const float *P,
                            uint32_t *ix)
{
    size_t t = 0;
    for (int k = 0; k < w->segment_count; k++) {
        const segment *a = &w->segments[k];
        if (a->ring || a->group >= SK_HAND_LINK_COUNT) continue;
        int a_end = a->vertex + n - 1;
        double reach = vertex_distance(P, a_end, a_end - 1);
        const segment *b = NULL;
        double best = INFINITY;
        for (int j = 0; j < w->segment_count; j++) {
            const segment *c = &w->segments[j];
            if (c->ring || c->group == a->group || c->group >= SK_HAND_LINK_COUNT) continue;
            double d = vertex_distance(P, a_end, c->vertex);
            if (d < best) best = d, b = c;
        }
        if (!b || best > reach) continue;
        /* b's start takes a's end back: no other arc's end is nearer to it */
        bool mutual = true;
        for (int j = 0; j < w->segment_count && mutual; j++) {
            const segment *c = &w->segments[j];
            if (c == a || c->ring || c->group == b->group || c->group >= SK_HAND_LINK_COUNT)
                continue;
            mutual = vertex_distance(P, c->vertex + n - 1, b->vertex) >= best;
        }
        double shift;
        const segment *a2 = matching_arc(next, a, &shift), *b2 = matching_arc(next, b, &shift);
        if (!mutual || !a2 || !b2 || vertex_distance(P, a2->vertex + n - 1, b2->vertex) > reach)
            continue;
        uint32_t a0 = (uint32_t)a_end, a1 = (uint32_t)b->vertex,
                 b0 = (uint32_t)(a2->vertex + n - 1), b1 = (uint32_t)b2->vertex;
        ix[6 * (t / 2)] = a0, ix[6 * (t / 2) + 1] = b0, ix[6 * (t / 2) + 2] = a1;
        ix[6 * (t / 2) + 3] = a1, ix[6 * (t / 2) + 4] = b0, ix[6 * (t / 2) + 5] = b1;
        t += 2;
    }
    return t;
}

static void free_work(slice_work *work, int count)
{
    if (!work) return;
    for (int s = 0; s < count; s++) {
        free(work[s].segments);
        free(work[s].theta);
        free(work[s].r);
    }
    free(work);
}

/* The settings with their defaults filled in (the neighbours' mode, 10 points, 45 deg),
 * checked. */
static sk_result resample_settings(const sk_hand_resample_desc *desc, sk_hand_resample_desc *d,
                                   sk_error *err)
{
    *d = desc ? *desc : (sk_hand_resample_desc){0};
    const sk_schema *schema = sk_schema_find(&sk_hand_scan_schema, "resample")->schema;
    sk_schema_apply_defaults(schema, d);
    return sk_schema_check(schema, d, "resample", err);
}

/* Every slice's points split into rings and arcs; false when out of memory. */
static bool find_segments(const sk_hand_slices *slices, double arc_gap, slice_work *work)
{
    int count = slices->count;
    bool failed = false;
#pragma omp parallel for schedule(dynamic, 1)
    for (int s = 0; s < count; s++) {
        size_t a = slices->first[s], b = slices->first[s + 1];
        slice_work *w = &work[s];
        w->theta = malloc(sizeof *w->theta * (b - a + 1));
        w->r = malloc(sizeof *w->r * (b - a + 1));
        w->segments = malloc(sizeof *w->segments * (b - a + 1));
        polar *scratch = malloc(sizeof *scratch * (b - a + 1));
        if (!w->theta || !w->r || !w->segments || !scratch) {
            free(scratch);
#pragma omp atomic write
            failed = true;
            continue;
        }
        slice_segments(slices, s, arc_gap, scratch, w);
        free(scratch);
    }
    return !failed;
}

/* Gives each segment its first vertex, n per segment, slice after slice; returns how many
 * vertices there are. */
static size_t number_vertices(slice_work *work, int count, int n)
{
    size_t vertices = 0;
    for (int s = 0; s < count; s++)
        for (int k = 0; k < work[s].segment_count; k++) {
            work[s].segments[k].vertex = (int)vertices;
            vertices += (size_t)n;
        }
    return vertices;
}

/* The most triangles the joins and bridges between consecutive slices can make. */
static size_t triangle_bound(const slice_work *work, int count, int n)
{
    size_t triangles = 0;
    for (int s = 0; s + 1 < count; s++)
        for (int k = 0; k < work[s].segment_count; k++) {
            const segment *with[8];
            triangles +=
                2 * (size_t)n * (size_t)partners(&work[s + 1], &work[s].segments[k], with, 8) + 2;
        }
    return triangles;
}

/* Each segment's n vertices at its sample angles (eq. 4.1) and radii (eq. 4.2), with their
 * angles and links. */
static void place_vertices(const sk_hand_slices *slices, const sk_hand_link_geometry *links,
                           const slice_work *work, sk_hand_resample_mode mode, int n,
                           double *angle_of, float *link_attr, sk_mesh *out)
{
    int count = slices->count;
#pragma omp parallel for schedule(dynamic, 1)
    for (int s = 0; s < count; s++) {
        double angles[256];
        for (int k = 0; k < work[s].segment_count; k++) {
            const segment *seg = &work[s].segments[k];
            sample_angles(work, s, count, seg, mode, theta_reference(links, seg->link), n, angles);
            sk_vec3d c = seg->centre;
            for (int i = 0; i < n; i++) {
                double rad = radius_at(&work[s], seg, angles[i]);
                size_t v = (size_t)seg->vertex + (size_t)i;
                angle_of[v] = angles[i];
                sk_vec3d p = {c.x + rad * cos(angles[i]), slices->y[s], c.z + rad * sin(angles[i])};
                out->positions[3 * v] = (float)p.x;
                out->positions[3 * v + 1] = (float)p.y;
                out->positions[3 * v + 2] = (float)p.z;
                /* a finger's ring: each vertex belongs to its nearest link */
                link_attr[v] =
                    (float)(seg->group >= SK_HAND_LINK_COUNT ? sk_hand_nearest_link(links, p, NULL)
                                                             : seg->link);
            }
        }
    }
}

/* The joins' counts for the stats: the segments of each kind and the quads' folds. */
typedef struct join_stats {
    double fold_sum, fold_max;
    size_t folds, rings, arcs;
} join_stats;

/* A ring and the arcs it joins (`seg` on slice s, `with` on s + 1): each arc zipped to the
 * part of the ring beside it. Returns the triangles written to ix. */
static size_t zip_ring_and_arcs(const segment *seg, const segment *const *with, int np,
                                const double *angle_of, int n, uint32_t *ix)
{
    size_t t = 0;
    for (int w = 0; w < np; w++) {
        const segment *ring = seg->ring ? seg : with[w], *arc = seg->ring ? with[w] : seg;
        uint32_t rv[256], av[256];
        double ra[256], aa[256];
        int pr = ring_portion(ring, arc, angle_of, n, rv, ra);
        for (int i = 0; i < n; i++)
            av[i] = (uint32_t)(arc->vertex + i), aa[i] = angle_of[arc->vertex + i];
        if (pr < 2) continue;
        t += seg->ring ? zipper(rv, ra, pr, av, aa, n, ix + 3 * t)
                       : zipper(av, aa, n, rv, ra, pr, ix + 3 * t);
    }
    return t;
}

/* The quads between a segment and its match m of the same kind on the next slice (around
 * a ring, along an arc), with their folds. Returns the triangles written to ix. */
static size_t join_quads(const segment *seg, const segment *m, int n, const float *P, uint32_t *ix,
                         join_stats *js)
{
    size_t t = 0;
    int quads = seg->ring ? n : n - 1;
    for (int i = 0; i < quads; i++) {
        uint32_t a0 = (uint32_t)(seg->vertex + i), a1 = (uint32_t)(seg->vertex + (i + 1) % n);
        uint32_t b0 = (uint32_t)(m->vertex + i), b1 = (uint32_t)(m->vertex + (i + 1) % n);
        uint32_t *tri = ix + 3 * t;
        tri[0] = a0, tri[1] = b0, tri[2] = a1;
        tri[3] = a1, tri[4] = b0, tri[5] = b1;
        t += 2;
        sk_vec3d pa0 = sk_v3d(P[3 * a0], P[3 * a0 + 1], P[3 * a0 + 2]);
        sk_vec3d pa1 = sk_v3d(P[3 * a1], P[3 * a1 + 1], P[3 * a1 + 2]);
        sk_vec3d pb0 = sk_v3d(P[3 * b0], P[3 * b0 + 1], P[3 * b0 + 2]);
        sk_vec3d pb1 = sk_v3d(P[3 * b1], P[3 * b1 + 1], P[3 * b1 + 2]);
        double f = fold_deg(pa0, pb0, pa1, pb1);
        if (isfinite(f)) {
            js->fold_sum += f;
            js->folds++;
            if (f > js->fold_max) js->fold_max = f;
        }
    }
    return t;
}

/* Every segment joined to its partners on the next slice, outward-facing; counts the
 * segments. Returns the triangles written to out's indices. */
static size_t join_slices(const slice_work *work, int count, int n, const double *angle_of,
                          sk_mesh *out, join_stats *js)
{
    size_t t = 0;
    for (int s = 0; s < count; s++)
        for (int k = 0; k < work[s].segment_count; k++) {
            const segment *seg = &work[s].segments[k];
            js->rings += seg->ring;
            js->arcs += !seg->ring;
            if (s + 1 >= count) continue;
            const segment *with[8];
            int np = partners(&work[s + 1], seg, with, 8);
            if (np == 0) continue;
            if (with[0]->ring != seg->ring)
                /* a ring and arcs: zip each arc to the part of the ring beside it */
                t += zip_ring_and_arcs(seg, with, np, angle_of, n, out->indices + 3 * t);
            else
                t += join_quads(seg, with[0], n, out->positions, out->indices + 3 * t, js);
        }
    return t;
}

sk_result sk_hand_resample(const sk_hand_slices *slices, const sk_hand_link_geometry *links,
                           const sk_hand_resample_desc *desc, sk_mesh *out,
                           sk_hand_resample_stats *stats, sk_error *err)
{
    memset(out, 0, sizeof *out);
    sk_hand_resample_desc d;
    sk_result r = resample_settings(desc, &d, err);
    if (r != SK_OK) return r;
    int count = slices->count, n = d.points_per_segment;
    double arc_gap = d.arc_gap_deg * SK_DEG_TO_RAD;
    slice_work *work = calloc((size_t)count, sizeof *work);
    if (!work) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "resampling %d slices", count);
    /* pass 1: rings and arcs of every slice */
    if (!find_segments(slices, arc_gap, work)) {
        free_work(work, count);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "resampling %d slices", count);
    }
    size_t vertices = number_vertices(work, count, n);
    /* triangles: at most 2n per join */
    size_t triangles = triangle_bound(work, count, n);
    if (vertices == 0 || triangles == 0) {
        free_work(work, count);
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "resampling: no two consecutive slices share a link "
                       "(too few points near the slices)");
    }
    r = sk_mesh_create(out, vertices, triangles, SK_MESH_NORMALS, err);
    float *link_attr = NULL;
    if (r == SK_OK) r = sk_mesh_add_attribute(out, "link", 1, &link_attr, err);
    double *angle_of = malloc(sizeof *angle_of * vertices);
    if (r == SK_OK && !angle_of) r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "resampling");
    if (r != SK_OK) {
        free(angle_of);
        free_work(work, count);
        sk_mesh_free(out);
        return r;
    }
    /* pass 2: the resampled vertices */
    place_vertices(slices, links, work, d.mode, n, angle_of, link_attr, out);
    /* pass 3: join each segment to its match on the next slice, outward-facing */
    join_stats js = {0};
    size_t t = join_slices(work, count, n, angle_of, out, &js);
    /* pass 4: the strips of neighbouring palm links bridged where they meet */
    for (int s = 0; s + 1 < count; s++)
        t += bridge_strips(&work[s], &work[s + 1], n, out->positions, out->indices + 3 * t);
    free_work(work, count);
    free(angle_of);
    out->triangle_count = t;
    r = sk_mesh_compute_normals(out, err);
    if (r != SK_OK) {
        sk_mesh_free(out);
        return r;
    }
    if (stats) {
        stats->rings = js.rings;
        stats->arcs = js.arcs;
        stats->fold_mean_deg = js.folds ? js.fold_sum / (double)js.folds : 0.0;
        stats->fold_max_deg = js.fold_max;
    }
    return SK_OK;
}
