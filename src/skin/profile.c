/* Height of one level at a point (paper sec. 3.2.1 (2), Figs. 5-7 and 12): body
 * coordinates from the cell centre p0 (the centroid of the straight polygon) towards the
 * point; x' = 10 |p - p0| / D(phi), with D(phi) the distance to the polygon along that
 * ray. For a convex polygon x' is the polygon's gauge, 10 max_e (p - p0) . n_e / h_e,
 * exact with no tables. Roundness rho moves the control points (all but the last) along
 * an arc: their x is scaled by g = (1 - rho) + rho min(1, R(phi) / D(phi)), where R(phi)
 * is h_e in the direction of each edge's normal and varies smoothly between neighbouring
 * normals, so rho = 1 gives contours through the scaled edge feet (a circle for a regular
 * polygon) that stay continuous at the corners. Returns height (mm) and its gradient. */
#include <math.h>

#include "skin/skin_internal.h"

/* The edge the ray from the centre through q meets: the hinted one if q lies inside its
 * sector by a margin (the same answer the full search gives), else the full gauge. */
static int centre_edge(const sk__sector *sec, int n, float qx, float qy, uint32_t *hint,
                       float *gauge)
{
    if (*hint < (uint32_t)n) {
        const sk__sector *a = &sec[*hint];
        float q1 = fabsf(qx) + fabsf(qy);
        if (a->ax * qy - a->ay * qx > q1 * a->an && qx * a->by - qy * a->bx > q1 * a->bn) {
            *gauge = a->gx * qx + a->gy * qy;
            return (int)*hint;
        }
    }
    float best = -INFINITY;
    int arg = 0;
    for (int j = 0; j < n; j++) {
        float gk = sec[j].gx * qx + sec[j].gy * qy;
        if (gk > best) best = gk, arg = j;
    }
    *hint = (uint32_t)arg;
    *gauge = best;
    return arg;
}

/* What a level's profile needs after the first step. */
enum { FLAT, SCALED, LAST_SEGMENT };

enum { ITEMS = SK__QUERY_BATCH * SK_SKIN_MAX_LEVELS };

void sk__profile_eval(const sk_skin *skin, int count, const int *level, const uint32_t *cell,
                      const float *px, const float *py, uint32_t *sector, float *z,
                      float (*grad)[2])
{
    float qx[ITEMS], qy[ITEMS], xq[ITEMS], gxq[ITEMS], gyq[ITEMS], r2[ITEMS];
    float s1[ITEMS], s2[ITEMS], g[ITEMS], ggx[ITEMS], ggy[ITEMS];
    const sk__sector *pair[ITEMS];
    int path[ITEMS];
    sk__newton newton[ITEMS];

    /* Step 1: the sector (x' and its gradient) and the pair of normals around q. */
    for (int k = 0; k < count; k++) {
        const sk__level *lv = &skin->levels[level[k]];
        const sk__cell *c = &lv->cells[cell[k]];
        const sk__sector *sec = lv->sectors + c->first_use;
        int n = (int)c->use_count;
        float x = px[k] - sec->cx, y = py[k] - sec->cy;
        float best;
        int arg = centre_edge(sec, n, x, y, &sector[level[k]], &best);
        float xk = 10.0f * best;
        g[k] = 1.0f, ggx[k] = 0.0f, ggy[k] = 0.0f;
        pair[k] = NULL;
        if (!(xk < 10.0f)) {
            path[k] = FLAT;
            continue;
        }
        if (xk < 0.0f) xk = 0.0f;
        qx[k] = x, qy[k] = y, xq[k] = xk;
        gxq[k] = 10.0f * sec[arg].gx, gyq[k] = 10.0f * sec[arg].gy; /* gradient of x' */
        float rr = x * x + y * y;
        r2[k] = rr;
        if (lv->roundness > 0.0f && rr > 0.0f && xk > 0.0f) {
            /* The pair of consecutive edge normals whose angle holds q: the edge the ray
               meets (arg) has its normal next to the ray, on one side or the other. */
            int i = arg;
            if (sec[arg].nx * y - sec[arg].ny * x < 0.0f) i = arg == 0 ? n - 1 : arg - 1;
            const sk__sector *pr = &sec[i];
            float a1 = pr->nx * y - pr->ny * x, a2 = x * pr->my - y * pr->mx;
            if (!(a1 >= 0.0f && a2 > 0.0f)) {
                /* a normal outside its edge's span (obtuse corner): search */
                for (int j = 0; j < n; j++) {
                    float c1 = sec[j].nx * y - sec[j].ny * x, c2 = x * sec[j].my - y * sec[j].mx;
                    if (c1 >= 0.0f && c2 > 0.0f) {
                        pr = &sec[j], a1 = c1, a2 = c2;
                        break;
                    }
                }
            }
            if (a1 + a2 > 0.0f) pair[k] = pr, s1[k] = a1, s2[k] = a2;
        }
        path[k] = SCALED;
    }
    /* Step 2: the roundness scale g and its gradient. */
    for (int k = 0; k < count; k++) {
        const sk__sector *pr = pair[k];
        if (!pr) continue;
        float rho = skin->levels[level[k]].roundness;
        float a1 = s1[k], a2 = s2[k], ss = a1 + a2, xk = xq[k];
        /* one division for both 1 / ss and 1 / r */
        float r = sqrtf(r2[k]), both = 1.0f / (ss * r);
        float iss = r * both, ir = ss * both, t = a1 * iss;
        float h1 = pr->h, h2 = pr->hm;
        float R = h1 + t * (h2 - h1);
        float inv = 0.1f * ir;
        float kappa = R * xk * inv; /* R / D(phi) */
        if (kappa < 1.0f) {
            /* grad t = (s2 grad s1 - s1 grad s2) / ss^2 */
            float g1x = -pr->ny, g1y = pr->nx, g2x = pr->my, g2y = -pr->mx;
            float dh = (h2 - h1) * iss * iss;
            float Rx = dh * (a2 * g1x - a1 * g2x), Ry = dh * (a2 * g1y - a1 * g2y);
            float k0 = kappa * ir * ir;
            float kx = (Rx * xk + R * gxq[k]) * inv - k0 * qx[k];
            float ky = (Ry * xk + R * gyq[k]) * inv - k0 * qy[k];
            g[k] = 1.0f - rho + rho * kappa;
            ggx[k] = rho * kx, ggy[k] = rho * ky;
        }
    }
    /* Step 3: z(x', g): the Newton guess in the last segment, else the scaled profile. */
    float dzdx[ITEMS], dzdg[ITEMS];
    for (int k = 0; k < count; k++) {
        const sk__profile *pr = &skin->levels[level[k]].profile;
        if (path[k] == FLAT) {
            z[k] = pr->z[pr->segment_count - 1][3];
            continue;
        }
        if (g[k] != 1.0f && xq[k] > g[k] * pr->last_start) {
            path[k] = LAST_SEGMENT;
            sk__last_segment_guess(pr, g[k], xq[k], &newton[k]);
        } else {
            z[k] = sk__profile_scaled(pr, g[k], xq[k], &dzdx[k], &dzdg[k]);
        }
    }
    /* Step 4: the Newton step; heights and gradients in mm. */
    for (int k = 0; k < count; k++) {
        const sk__level *lv = &skin->levels[level[k]];
        if (path[k] == LAST_SEGMENT)
            z[k] = sk__last_segment_finish(&lv->profile, xq[k], &newton[k], &dzdx[k], &dzdg[k]);
        if (path[k] == FLAT) {
            grad[k][0] = grad[k][1] = 0.0f;
        } else {
            grad[k][0] = (dzdx[k] * gxq[k] + dzdg[k] * ggx[k]) * lv->z_scale;
            grad[k][1] = (dzdx[k] * gyq[k] + dzdg[k] * ggy[k]) * lv->z_scale;
        }
        z[k] *= lv->z_scale;
    }
}
