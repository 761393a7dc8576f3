/* Edge perturbation by midpoint displacement (paper sec. 4.2 (2), after Fournier, Fussell
 * and Carpenter 1982): at division depth n the midpoint of a segment of length L moves by
 *   V = A * 2^(-n h) * Rnd * L,   Rnd ~ N(0, 1).
 * The polyline is kept as offsets f(t) across the straight edge at t = k / 2^depth, so
 * every point keeps its parameter along the edge. The offsets stay inside a support
 * triangle over the edge on each side (within the two cells' fan triangles), which keeps
 * perturbed edges from ever crossing one another. Randomness: a stream keyed by (seed,
 * level, the edge's two cells), read in a fixed order. */
#include <math.h>

#include "models/skin/skin_internal.h"

#define SK__SUPPORT_FILL 0.8 /* offsets stay within this share of the support height */

void sk__support(double ax, double ay, double bx, double by, double px, double py, double *t_apex,
                 double *h_apex)
{
    double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
    double tp = ((px - ax) * ex + (py - ay) * ey) / len2;
    double hp = fabs(ex * (py - ay) - ey * (px - ax)) / sqrt(len2);
    /* The triangle (a, b, p) is the fan triangle of the left site; the apex is moved
       inside it so the support vanishes at both ends of the edge. */
    double t = tp < 0.1 ? 0.1 : (tp > 0.9 ? 0.9 : tp);
    double h;
    if (tp >= 1.0)
        h = hp * t / tp;
    else if (tp <= 0.0)
        h = hp * (1.0 - t) / (1.0 - tp);
    else
        h = hp * sk__tent(t, tp);
    *t_apex = t;
    *h_apex = h;
}

void sk__perturb_edge(const sk_skin *skin, int level, uint64_t edge_key, double length,
                      double t_apex, double h_apex, float *f)
{
    const sk__level *lv = &skin->levels[level];
    int depth = lv->depth, count = 1 << depth;
    double fd[(1 << 10) + 1];
    fd[0] = 0.0, fd[count] = 0.0;
    /* One stream per edge, normals drawn in Box-Muller pairs in a fixed order. */
    sk_rng rng = sk_rng_make(skin->desc.seed, edge_key, 0x50455254ULL, (uint64_t)level);
    double spare = 0.0;
    bool have_spare = false;
    for (int n = 1; n <= depth; n++) {
        int step = count >> n;
        double amp = lv->amp[n];
        for (int k = step; k < count; k += 2 * step) {
            double rnd;
            if (have_spare) {
                rnd = spare, have_spare = false;
            } else {
                double u1 = 1.0 - sk_rng_uniform(&rng), u2 = sk_rng_uniform(&rng);
                double r = sqrt(-2.0 * log(u1)), a = 2.0 * SK_PI * u2;
                rnd = r * cos(a), spare = r * sin(a), have_spare = true;
            }
            double fl = fd[k - step], fr = fd[k + step];
            double dt = 2.0 * step / (double)count * length;
            double seg = sqrt(dt * dt + (fr - fl) * (fr - fl));
            double v = amp * rnd * seg;
            double t = (double)k / count;
            double hs = h_apex * sk__tent(t, t_apex) * SK__SUPPORT_FILL;
            double val = 0.5 * (fl + fr) + v;
            fd[k] = val > hs ? hs : (val < -hs ? -hs : val);
        }
    }
    for (int k = 0; k <= count; k++) f[k] = (float)fd[k];
}
