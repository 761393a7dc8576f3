/* Shared edges (paper sec. 3.2.1 (1), Fig. 4): an edge between two cells is perturbed
 * once, keyed by the pair of cells, and both cells use the same record, so the perturbed
 * polygons have no gaps and no overlaps. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/skin/skin_internal.h"

#define SK__SUPPORT_REACH 3.0

/* One shared edge: its record and perturbation, and both uses' lines. */
/* The two uses of edge e and their cells. */
typedef struct edge_pair {
    uint32_t use_left, use_right, cell_left, cell_right;
} edge_pair;

/* One shared edge: its record and perturbation, and both uses' lines. */
static void build_edge(sk_skin *skin, int level, const sk__edge_key *key, const edge_pair *ep,
                       uint32_t e, const double *site_left_y)
{
    sk__level *lv = &skin->levels[level];
    double(*m)[2] = lv->m, (*mi)[2] = lv->minv;
    uint32_t ui = ep->use_left, cl = ep->cell_left, cr = ep->cell_right;
    sk__use *ul = &lv->uses[ui], *ur = &lv->uses[ep->use_right];
    const sk__cell *cell_l = &lv->cells[cl];
    uint32_t next = ui + 1 == cell_l->first_use + cell_l->use_count ? cell_l->first_use : ui + 1;
    double ax = lv->vxy[2 * ui], ay = lv->vxy[2 * ui + 1];
    double bx = lv->vxy[2 * next], by = lv->vxy[2 * next + 1];
    /* pre-stretch geometry */
    double azx = mi[0][0] * ax + mi[0][1] * ay, azy = mi[1][0] * ax + mi[1][1] * ay;
    double bzx = mi[0][0] * bx + mi[0][1] * by, bzy = mi[1][0] * bx + mi[1][1] * by;
    double px = site_left_y[2 * ui], py = site_left_y[2 * ui + 1];
    double pzx = mi[0][0] * px + mi[0][1] * py, pzy = mi[1][0] * px + mi[1][1] * py;
    double ex = bzx - azx, ey = bzy - azy, len2 = ex * ex + ey * ey, len = sqrt(len2);
    sk__edge *E = &lv->edges[e];
    if (!(len > 0)) return; /* degenerate: the uses stay unpaired */
    /* Midpoint displacement runs in pre-stretch space (the paper perturbs, then
       stretches): offsets along the pre-stretch normal, towards the left site. */
    double nzx = -ey / len, nzy = ex / len;
    double t_apex, h_apex;
    sk__support(azx, azy, bzx, bzy, pzx, pzy, &t_apex, &h_apex);
    float *f = lv->f + (size_t)e * (size_t)lv->f_count;
    /* In y space the stretched offset M n f has a part across the edge and a part
       along it; the part along it only slides points along the edge (and can fold a
       strongly stretched edge), so the polyline keeps the part across it: a graph over
       the edge, in a support triangle inside the y-space fan triangle. */
    double eyx = bx - ax, eyy = by - ay, leny2 = eyx * eyx + eyy * eyy, leny = sqrt(leny2);
    double nwx = -eyy / leny, nwy = eyx / leny;
    double across = (m[0][0] * nzx + m[0][1] * nzy) * nwx + (m[1][0] * nzx + m[1][1] * nzy) * nwy;
    double ty_apex, hy_apex;
    sk__support(ax, ay, bx, by, px, py, &ty_apex, &hy_apex);
    double fmax = 0;
    if (lv->perturbed) {
        uint64_t hash = sk_hash(key->k0, key->k1, (uint64_t)level, 0x45444745ULL);
        sk__perturb_edge(skin, level, hash, len, t_apex, h_apex, f);
        /* The stretch may not make the polyline steeper against its edge than it was
           before the stretch. Across an edge that the stretch leaves short (the ends of
           a cell drawn out 20 x) the stretched offsets grow 20 x while the edge does not:
           a sawtooth far steeper than any unstretched furrow, whose warp shears the
           children it carries into chevrons and slivers. Such an edge keeps the shape of
           its polyline at the steepness it had before the stretch. */
        double slope_z = 0, slope_y = 0;
        for (int k = 0; k + 1 < lv->f_count; k++) {
            double df = fabs((double)f[k + 1] - f[k]);
            slope_z = slope_z > df ? slope_z : df;
        }
        slope_y = slope_z * fabs(across) / leny;
        slope_z /= len;
        if (slope_y > slope_z * (1.0 + 1e-9)) across *= slope_z / slope_y;
        double raw = 0;
        for (int k = 0; k < lv->f_count; k++)
            raw = raw > fabs(f[k] * across) ? raw : fabs(f[k] * across);
        /* The support reaches no farther from the edge than a few times the polyline's
           excursion: the warp stays local, so a strongly stretched level does not
           shear its children far from its edges. */
        hy_apex = sk__min(hy_apex, SK__SUPPORT_REACH * raw);
        for (int k = 0; k < lv->f_count; k++) {
            double t = (double)k / (lv->f_count - 1);
            double hs = 0.8 * hy_apex * sk__tent(t, ty_apex);
            double v = f[k] * across;
            f[k] = (float)(v > hs ? hs : (v < -hs ? -hs : v));
            fmax = fmax > fabs(f[k]) ? fmax : fabs(f[k]);
        }
    }
    E->ax = (float)ax, E->ay = (float)ay, E->bx = (float)bx, E->by = (float)by;
    E->atx = (float)(eyx / leny2), E->aty = (float)(eyy / leny2);
    E->asx = (float)nwx, E->asy = (float)nwy;
    E->dx = (float)nwx, E->dy = (float)nwy;
    E->t_apex = (float)ty_apex, E->h_apex = (float)hy_apex;
    E->rise = (float)(hy_apex / ty_apex), E->fall = (float)(hy_apex / (1.0 - ty_apex));
    E->bulge = (float)fmax;
    E->shx = ur->shx, E->shy = ur->shy;
    E->left = cl, E->right = cr;
    E->f_first = e * (uint32_t)lv->f_count;
    /* Both sides take their line from the record: exactly complementary half-planes. */
    double nyx = nwx, nyy = nwy;
    ul->nx = (float)-nyx, ul->ny = (float)-nyy;
    ul->d = (float)-(nyx * ax + nyy * ay);
    ur->nx = (float)nyx, ur->ny = (float)nyy;
    ur->d = (float)(nyx * (ax - ur->shx) + nyy * (ay - ur->shy));
    ul->edge = e, ur->edge = e;
    ul->bulge = ur->bulge = E->bulge;
    ul->neighbour = cr, ur->neighbour = cl;
}

sk_result sk__build_edges(sk_skin *skin, int level, const sk__edge_key *keys,
                          const double *site_left_y, sk_error *err)
{
    sk__level *lv = &skin->levels[level];
    /* Each left use finds its right use among the uses of the right cell (k0 holds both
       cells); edges are numbered in the order of their left uses. */
    edge_pair *pairs = malloc(sizeof(edge_pair) * (lv->use_count ? lv->use_count : 1));
    if (!pairs) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for edges");
    uint32_t e = 0;
    for (uint32_t c = 0; c < lv->cell_count; c++) {
        const sk__cell *cell = &lv->cells[c];
        for (uint32_t u = cell->first_use; u < cell->first_use + cell->use_count; u++) {
            const sk__edge_key *kl = &keys[u];
            if (kl->side != SK__SIDE_LEFT) continue;
            uint32_t right = (uint32_t)(kl->k0 & 0xffffffffu);
            const sk__cell *rc = &lv->cells[right];
            for (uint32_t v = rc->first_use; v < rc->first_use + rc->use_count; v++) {
                const sk__edge_key *kr = &keys[v];
                if (kr->side == SK__SIDE_RIGHT && kr->k0 == kl->k0 && kr->k1 == kl->k1) {
                    pairs[e].use_left = u, pairs[e].use_right = v;
                    pairs[e].cell_left = c, pairs[e].cell_right = right;
                    e++;
                    break;
                }
            }
        }
    }
    lv->f_count = (1 << lv->depth) + 1;
    lv->f_step = 1.0f / (float)(lv->f_count - 1);
    lv->edges = calloc(e ? e : 1, sizeof(sk__edge));
    lv->f = calloc((e ? e : 1) * (size_t)lv->f_count, sizeof(float));
    if (!lv->edges || !lv->f) {
        free(pairs);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %u edges", e);
    }
    /* Each edge draws its own random numbers from its key: any order, same result. */
#pragma omp parallel for schedule(dynamic, 64) if (e >= SK__PARALLEL_HEAVY_ITEMS)
    for (long q = 0; q < (long)e; q++)
        build_edge(skin, level, &keys[pairs[q].use_left], &pairs[q], (uint32_t)q, site_left_y);
    free(pairs);
    lv->edge_count = e;
    return SK_OK;
}
