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
static int centre_edge(const sk__use *u, int n, float qx, float qy, uint32_t *hint, float *gauge)
{
    if (*hint < (uint32_t)n) {
        int k = (int)*hint;
        const sk__use *a = &u[k], *b = &u[k + 1 == n ? 0 : k + 1];
        float q1 = fabsf(qx) + fabsf(qy);
        if (a->cvx * qy - a->cvy * qx > q1 * a->cvn && qx * b->cvy - qy * b->cvx > q1 * b->cvn) {
            *gauge = a->acx * qx + a->acy * qy;
            return k;
        }
    }
    float best = -INFINITY;
    int arg = 0;
    for (int j = 0; j < n; j++) {
        float gk = u[j].acx * qx + u[j].acy * qy;
        if (gk > best) best = gk, arg = j;
    }
    *hint = (uint32_t)arg;
    *gauge = best;
    return arg;
}

float sk__profile_eval(const sk__level *lv, uint32_t c, float px, float py, float grad[2],
                       uint32_t *hint)
{
    const sk__cell *cell = &lv->cells[c];
    const sk__use *u = lv->uses + cell->first_use;
    int n = (int)cell->use_count;
    float qx = px - cell->cx, qy = py - cell->cy;
    float best;
    int arg = centre_edge(u, n, qx, qy, hint, &best);
    float xq = 10.0f * best;
    const sk__profile *pr = &lv->profile;
    grad[0] = grad[1] = 0.0f;
    if (!(xq < 10.0f)) return pr->z[pr->segment_count - 1][3] * lv->z_scale;
    if (xq < 0.0f) xq = 0.0f;
    float gxq = 10.0f * u[arg].acx, gyq = 10.0f * u[arg].acy; /* gradient of x' */
    float g = 1.0f, ggx = 0.0f, ggy = 0.0f;                   /* roundness scale */
    float rho = lv->roundness;
    float r2 = qx * qx + qy * qy;
    if (rho > 0.0f && r2 > 0.0f && xq > 0.0f) {
        /* The pair of consecutive edge normals whose angle holds q: the edge the ray
           meets (arg) has its normal next to the ray, on one side or the other. */
        int i = arg;
        if (u[arg].nx * qy - u[arg].ny * qx < 0.0f) i = arg == 0 ? n - 1 : arg - 1;
        int i1 = i + 1 == n ? 0 : i + 1;
        float s1 = u[i].nx * qy - u[i].ny * qx, s2 = qx * u[i1].ny - qy * u[i1].nx;
        if (!(s1 >= 0.0f && s2 > 0.0f)) {
            /* a normal outside its edge's span (obtuse corner): search */
            for (int k = 0; k < n; k++) {
                int k1 = k + 1 == n ? 0 : k + 1;
                float c1 = u[k].nx * qy - u[k].ny * qx, c2 = qx * u[k1].ny - qy * u[k1].nx;
                if (c1 >= 0.0f && c2 > 0.0f) {
                    i = k, i1 = k1, s1 = c1, s2 = c2;
                    break;
                }
            }
        }
        float ss = s1 + s2;
        if (ss > 0.0f) {
            /* one division for both 1 / ss and 1 / r */
            float r = sqrtf(r2), both = 1.0f / (ss * r);
            float iss = r * both, ir = ss * both, t = s1 * iss;
            float h1 = u[i].hc, h2 = u[i1].hc;
            float R = h1 + t * (h2 - h1);
            float inv = 0.1f * ir;
            float kappa = R * xq * inv; /* R / D(phi) */
            if (kappa < 1.0f) {
                /* grad t = (s2 grad s1 - s1 grad s2) / ss^2 */
                float g1x = -u[i].ny, g1y = u[i].nx, g2x = u[i1].ny, g2y = -u[i1].nx;
                float dh = (h2 - h1) * iss * iss;
                float Rx = dh * (s2 * g1x - s1 * g2x), Ry = dh * (s2 * g1y - s1 * g2y);
                float k0 = kappa * ir * ir;
                float kx = (Rx * xq + R * gxq) * inv - k0 * qx;
                float ky = (Ry * xq + R * gyq) * inv - k0 * qy;
                g = 1.0f - rho + rho * kappa;
                ggx = rho * kx, ggy = rho * ky;
            }
        }
    }
    float dzdx, dzdg;
    float z = sk__bezier_solve(pr, g, xq, &dzdx, &dzdg);
    grad[0] = (dzdx * gxq + dzdg * ggx) * lv->z_scale;
    grad[1] = (dzdx * gyq + dzdg * ggy) * lv->z_scale;
    return z * lv->z_scale;
}
