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

#include "models/skin/skin_internal.h"

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

/* What an item's profile needs after the first step. */
enum { FLAT, SCALED, LAST_SEGMENT };

enum { ITEMS = SK__QUERY_BATCH * SK_SKIN_MAX_LEVELS };

void sk__profile_eval(const sk_skin *skin, int L, int m, const uint32_t *cell, const float *px,
                      const float *py, uint32_t *sector, float *z, float (*grad)[2])
{
    float xq[ITEMS], gxq[ITEMS], gyq[ITEMS], qx[ITEMS], qy[ITEMS];
    float g[ITEMS], ggx[ITEMS], ggy[ITEMS];
    float dzdx[ITEMS], dzdg[ITEMS];
    int path[ITEMS];
    sk__newton newton[ITEMS];

    /* Step 1: the sector (x' and its gradient), the pair of normals around q and the
       roundness scale g. */
    for (int k = 0; k < L; k++) {
        const sk__level *lv = &skin->levels[k];
        float rho = lv->roundness;
        bool round = rho > 0.0f;
        for (int i = k * m; i < (k + 1) * m; i++) {
            const sk__cell *c = &lv->cells[cell[i]];
            const sk__sector *sec = lv->sectors + c->first_use;
            int n = (int)c->use_count;
            float x = px[i] - sec->cx, y = py[i] - sec->cy;
            qx[i] = x, qy[i] = y;
            float best;
            int arg = centre_edge(sec, n, x, y, &sector[k], &best);
            float xk = 10.0f * best;
            g[i] = 1.0f, ggx[i] = 0.0f, ggy[i] = 0.0f;
            if (!(xk < 10.0f)) {
                path[i] = FLAT;
                continue;
            }
            path[i] = SCALED;
            if (xk < 0.0f) xk = 0.0f;
            xq[i] = xk;
            gxq[i] = 10.0f * sec[arg].gx, gyq[i] = 10.0f * sec[arg].gy; /* gradient of x' */
            float rr = x * x + y * y;
            if (!(round && rr > 0.0f && xk > 0.0f)) continue;
            /* The pair of consecutive edge normals whose angle holds q: the edge the ray
               meets (arg) has its normal next to the ray, on one side or the other. */
            const sk__sector *pr = &sec[arg];
            float a1 = pr->nx * y - pr->ny * x, a2;
            if (a1 < 0.0f) {
                pr = &sec[arg == 0 ? n - 1 : arg - 1];
                a2 = -a1, a1 = pr->nx * y - pr->ny * x;
            } else {
                a2 = x * pr->my - y * pr->mx;
            }
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
            float ss = a1 + a2;
            if (!(ss > 0.0f)) continue;
            /* the roundness scale g and its gradient; one division for 1 / ss and 1 / r */
            float r = sqrtf(rr), both = 1.0f / (ss * r);
            float iss = r * both, ir = ss * both, t = a1 * iss;
            float h1 = pr->h, h2 = pr->hm;
            float R = h1 + t * (h2 - h1);
            float inv = 0.1f * ir;
            float kappa = R * xk * inv; /* R / D(phi) */
            if (kappa < 1.0f) {
                /* grad t = (s2 grad s1 - s1 grad s2) / ss^2, grad s1 = (-ny, nx) of normal 1,
                   grad s2 = (my, -mx) of normal 2 */
                float dh = (h2 - h1) * iss * iss;
                float Rx = dh * (-a2 * pr->ny - a1 * pr->my), Ry = dh * (a2 * pr->nx + a1 * pr->mx);
                float k0 = kappa * ir * ir;
                float kx = (Rx * xk + R * gxq[i]) * inv - k0 * x;
                float ky = (Ry * xk + R * gyq[i]) * inv - k0 * y;
                g[i] = 1.0f - rho + rho * kappa;
                ggx[i] = rho * kx, ggy[i] = rho * ky;
            }
        }
        /* z(x', g): the Newton guess in the last segment, else the scaled profile */
        const sk__profile *prof = &lv->profile;
        for (int i = k * m; i < (k + 1) * m; i++) {
            if (path[i] == FLAT) {
                z[i] = prof->z[prof->segment_count - 1][3];
            } else if (g[i] != 1.0f && xq[i] > g[i] * prof->last_start) {
                path[i] = LAST_SEGMENT;
                sk__last_segment_guess(prof, g[i], xq[i], &newton[i]);
            } else {
                z[i] = sk__profile_scaled(prof, g[i], xq[i], &dzdx[i], &dzdg[i]);
            }
        }
    }
    /* Step 3: the Newton step; heights and gradients in mm. */
    bool radial = skin->desc.normal_model == SK_SKIN_NORMAL_PROFILE;
    for (int k = 0; k < L; k++) {
        const sk__level *lv = &skin->levels[k];
        float zs = lv->z_scale;
        for (int i = k * m; i < (k + 1) * m; i++) {
            if (path[i] == LAST_SEGMENT)
                z[i] = sk__last_segment_finish(&lv->profile, xq[i], &newton[i], &dzdx[i], &dzdg[i]);
            if (path[i] == FLAT) {
                grad[i][0] = grad[i][1] = 0.0f;
            } else {
                float gx = (dzdx[i] * gxq[i] + dzdg[i] * ggx[i]) * zs;
                float gy = (dzdx[i] * gyq[i] + dzdg[i] * ggy[i]) * zs;
                if (radial) {
                    /* Fig. 7: N1 = (S_x d, S_z) with S the normal of the profile drawn
                       along the ray d from the centre (x' = 10 at the boundary, D(phi)
                       away): the slope dz/dr of that ray, the gradient's part along d
                       (x' grows along the ray as r / D, g not at all). The ray runs in
                       the level's pre-stretch space, where the paper divides its cells,
                       and the slope is stretched with the ridge: with u = M^-1 q the ray
                       there, the slope vector is (g . q / |u|^2) M^-T u (u = q when the
                       level is not stretched). */
                    const float(*mi)[2] = lv->minvf;
                    float ux = mi[0][0] * qx[i] + mi[0][1] * qy[i];
                    float uy = mi[1][0] * qx[i] + mi[1][1] * qy[i];
                    float uu = ux * ux + uy * uy;
                    float s = uu > 0.0f ? (gx * qx[i] + gy * qy[i]) / uu : 0.0f;
                    gx = s * (mi[0][0] * ux + mi[1][0] * uy);
                    gy = s * (mi[0][1] * ux + mi[1][1] * uy);
                }
                grad[i][0] = gx, grad[i][1] = gy;
            }
            z[i] *= zs;
        }
    }
}
