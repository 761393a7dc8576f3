/* Phase (Kawai 2000 eqs. (2), (3)): Phi(t, y) = integral from 0 to y of G'(t, y') dy', so
 * that phi(r, theta, y) = Phi(t, y) / R(t, theta) with t = T(r, theta). The closed-form
 * parts of g are integrated exactly; the fractal dg is integrated once per tree into a
 * (t, y) table. dg is linear between samples along y, so the table holds the exact
 * integral at the samples and the lookup adds the exact quadratic in between: dPhi/dy
 * equals the interpolated dg, which keeps the phase consistent with the fibre direction. */
#include <math.h>

#include "base/parallel.h"
#include "models/wood/grain.h"

bool sk__phase_build(sk__grain *g)
{
    size_t row = (size_t)g->ny + 1;
#pragma omp parallel for schedule(static) if (sk__parallel_worth((double)g->nt * g->ny, 3.0))
    for (int i = 0; i < g->nt; i++) {
        const float *d = g->dg + (size_t)i * row;
        float *p = g->phi + (size_t)i * row;
        double acc = 0.0;
        p[0] = 0.0f;
        for (int j = 0; j < g->ny; j++) {
            acc += 0.5 * g->dy * ((double)d[j] + d[j + 1]);
            p[j + 1] = (float)acc;
        }
        /* zero-mean rows integrate to 0 over the period; remove the rounding residue */
        for (int j = 1; j <= g->ny; j++) p[j] = (float)(p[j] - acc * j / g->ny);
    }
    return true;
}
