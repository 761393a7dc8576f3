/* Skin weights of the hand surface. Nearest link: the thesis's rule (4.1.5), every vertex
 * moves with the link whose flesh it lies on. Smooth: near a joint the flesh of both
 * links is close, and the weight of a link falls off as (1 - x)^2 with x the vertex's
 * distance to that link's flesh beyond the nearest one's, over a width of a few mm
 * (along the link: how far the joint's blend reaches; around it: the same on every
 * side). Only links next to the nearest one in the tree (parent, children; the palm's
 * links among themselves) take part, so neighbouring fingers never pull on each other.
 * At most 4 links, largest first, summing to 1. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

static bool is_palm_link(int link)
{
    return link == 0 || link == sk__hand_first_link(sk__hand_finger_of_link(link));
}

static bool adjacent(const sk_hand_skeleton *s, int a, int b)
{
    if (a == b) return true;
    if (s->parent[a] == b || s->parent[b] == a) return true;
    return is_palm_link(a) && is_palm_link(b);
}

void sk__hand_weights_compute(const sk__hand_field *f, const sk_hand_skeleton *s,
                              const float *positions, size_t vertex_count, uint16_t *nearest_links,
                              float *nearest_weights, uint16_t *smooth_links, float *smooth_weights)
{
    double sb = s->hand_breadth_mm / 85.0;
#pragma omp parallel for schedule(static) if (vertex_count > 2048)
    for (size_t v = 0; v < vertex_count; v++) {
        sk_vec3d p = sk_v3d(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
        double d[SK_HAND_LINK_COUNT];
        for (int j = 0; j < SK_HAND_LINK_COUNT; j++) d[j] = DBL_MAX;
        for (int i = 0; i < f->count; i++) {
            const sk__hand_prim *pr = &f->prim[i];
            if (pr->link < 0 || pr->nail) continue;
            double e = sk__hand_prim_eval(pr, p);
            if (e < d[pr->link]) d[pr->link] = e;
        }
        int best = 0;
        for (int j = 1; j < SK_HAND_LINK_COUNT; j++)
            if (d[j] < d[best]) best = j;
        memset(nearest_links + 4 * v, 0, 4 * sizeof *nearest_links);
        memset(nearest_weights + 4 * v, 0, 4 * sizeof *nearest_weights);
        nearest_links[4 * v] = (uint16_t)best;
        nearest_weights[4 * v] = 1.0f;
        double w[SK_HAND_LINK_COUNT];
        double total = 0;
        for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
            w[j] = 0;
            if (!adjacent(s, best, j) || d[j] == DBL_MAX) continue;
            double width = (is_palm_link(j) && is_palm_link(best) ? 10.0 : 4.0) * sb;
            double x = (d[j] - d[best]) / width;
            if (x < 1.0) w[j] = (1.0 - x) * (1.0 - x);
        }
        /* the 4 largest */
        int pick[4] = {best};
        int n = 1;
        total = w[best];
        for (; n < 4; n++) {
            int m = -1;
            for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
                bool taken = false;
                for (int k = 0; k < n; k++) taken |= pick[k] == j;
                if (!taken && w[j] > 0 && (m < 0 || w[j] > w[m])) m = j;
            }
            /* weights under 2 % are dropped (the rest renormalised): they move a vertex by
               less than 2 % of the links' relative motion and cost a blend each */
            if (m < 0 || w[m] < 0.02 * total) break;
            pick[n] = m;
            total += w[m];
        }
        memset(smooth_links + 4 * v, 0, 4 * sizeof *smooth_links);
        memset(smooth_weights + 4 * v, 0, 4 * sizeof *smooth_weights);
        float sum = 0;
        for (int k = 0; k < n; k++) {
            smooth_links[4 * v + k] = (uint16_t)pick[k];
            smooth_weights[4 * v + k] = (float)(w[pick[k]] / total);
            sum += smooth_weights[4 * v + k];
        }
        /* exact sum 1 in float: the remainder on the largest */
        smooth_weights[4 * v] += 1.0f - sum;
    }
}
