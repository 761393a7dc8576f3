/* Stretch (paper parameter 3, sec. 3.2.2 and 4.2 (3)): x' = Sx x, y' = Sy y, here about
 * an axis turned by stretch_angle. Applied to a level's polygons after division and
 * perturbation, so every level is divided in its own pre-stretch space z = M^-1 y. */
#include <math.h>

#include "models/skin/skin_internal.h"

void sk__stretch_matrices(const sk_skin_level *lv, double m[2][2], double minv[2][2])
{
    double c = cos(lv->stretch_angle), s = sin(lv->stretch_angle);
    double sx = lv->stretch[0], sy = lv->stretch[1];
    /* M = R diag(sx, sy) R^T */
    m[0][0] = c * c * sx + s * s * sy;
    m[0][1] = c * s * (sx - sy);
    m[1][0] = m[0][1];
    m[1][1] = s * s * sx + c * c * sy;
    minv[0][0] = c * c / sx + s * s / sy;
    minv[0][1] = c * s * (1.0 / sx - 1.0 / sy);
    minv[1][0] = minv[0][1];
    minv[1][1] = s * s / sx + c * c / sy;
}
