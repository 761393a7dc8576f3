/* Shared edges (paper sec. 3.2.1 (1), Fig. 4): an edge between two cells is perturbed
 * once, keyed by the pair of cells, and both cells use the same record, so the perturbed
 * polygons have no gaps and no overlaps. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "skin/skin_internal.h"

#define SK__SUPPORT_REACH 3.0

static int key_cmp(const void *pa, const void *pb)
{
    const sk__edge_key *a = pa, *b = pb;
    if (a->k0 != b->k0) return a->k0 < b->k0 ? -1 : 1;
    if (a->k1 != b->k1) return a->k1 < b->k1 ? -1 : 1;
    if (a->side != b->side) return a->side < b->side ? -1 : 1;
    return a->use < b->use ? -1 : (a->use > b->use);
}

/* One shared edge: its record and perturbation, and both uses' lines. */
static void build_edge(sk_skin *skin, int level, const sk__edge_key *kl, const sk__edge_key *kr,
                       uint32_t e, const uint32_t *use_owner, const double *site_left_y)
{
    sk__level *lv = &skin->levels[level];
    double(*m)[2] = lv->m, (*mi)[2] = lv->minv;
    sk__use *ul = &lv->uses[kl->use], *ur = &lv->uses[kr->use];
    uint32_t cl = use_owner[kl->use], cr = use_owner[kr->use];
    const sk__cell *cell_l = &lv->cells[cl];
    uint32_t next =
        kl->use + 1 == cell_l->first_use + cell_l->use_count ? cell_l->first_use : kl->use + 1;
    double ax = lv->vxy[2 * kl->use], ay = lv->vxy[2 * kl->use + 1];
    double bx = lv->vxy[2 * next], by = lv->vxy[2 * next + 1];
    /* pre-stretch geometry */
    double azx = mi[0][0] * ax + mi[0][1] * ay, azy = mi[1][0] * ax + mi[1][1] * ay;
    double bzx = mi[0][0] * bx + mi[0][1] * by, bzy = mi[1][0] * bx + mi[1][1] * by;
    double px = site_left_y[2 * kl->use], py = site_left_y[2 * kl->use + 1];
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
        uint64_t key = sk_hash(kl->k0, kl->k1, (uint64_t)level, 0x45444745ULL);
        sk__perturb_edge(skin, level, key, len, t_apex, h_apex, f);
        double raw = 0;
        for (int k = 0; k < lv->f_count; k++)
            raw = raw > fabs(f[k] * across) ? raw : fabs(f[k] * across);
        /* The support reaches no farther from the edge than a few times the polyline's
           excursion: the warp stays local, so a strongly stretched level does not
           shear its children far from its edges. */
        hy_apex = fmin(hy_apex, SK__SUPPORT_REACH * raw);
        for (int k = 0; k < lv->f_count; k++) {
            double t = (double)k / (lv->f_count - 1);
            double hs = 0.8 * hy_apex * fmin(t / ty_apex, (1.0 - t) / (1.0 - ty_apex));
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
    ul->neighbour = cr, ur->neighbour = cl;
}

sk_result sk__build_edges(sk_skin *skin, int level, sk__edge_key *keys, size_t key_count,
                          const double *site_left_y, sk_error *err)
{
    sk__level *lv = &skin->levels[level];
    qsort(keys, key_count, sizeof *keys, key_cmp);
    uint32_t *use_owner = malloc(sizeof(uint32_t) * (lv->use_count ? lv->use_count : 1));
    if (!use_owner) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for edges");
    for (uint32_t c = 0; c < lv->cell_count; c++)
        for (uint32_t k = 0; k < lv->cells[c].use_count; k++)
            use_owner[lv->cells[c].first_use + k] = c;

    size_t pairs = 0;
    for (size_t i = 0; i + 1 < key_count; i++)
        if (keys[i].k0 == keys[i + 1].k0 && keys[i].k1 == keys[i + 1].k1 && keys[i].side == 0 &&
            keys[i + 1].side == 1)
            pairs++;
    lv->f_count = (1 << lv->depth) + 1;
    lv->edges = calloc(pairs ? pairs : 1, sizeof(sk__edge));
    lv->f = calloc((pairs ? pairs : 1) * (size_t)lv->f_count, sizeof(float));
    if (!lv->edges || !lv->f) {
        free(use_owner);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu edges", pairs);
    }
    uint32_t *pair_at = malloc(sizeof(uint32_t) * (pairs ? pairs : 1));
    if (!pair_at) {
        free(use_owner);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu edges", pairs);
    }
    uint32_t e = 0;
    for (size_t i = 0; i + 1 < key_count; i++)
        if (keys[i].k0 == keys[i + 1].k0 && keys[i].k1 == keys[i + 1].k1 && keys[i].side == 0 &&
            keys[i + 1].side == 1)
            pair_at[e++] = (uint32_t)i;
            /* Each edge draws its own random numbers from its key: any order, same result. */
#pragma omp parallel for schedule(static)
    for (long q = 0; q < (long)e; q++)
        build_edge(skin, level, &keys[pair_at[q]], &keys[pair_at[q] + 1], (uint32_t)q, use_owner,
                   site_left_y);
    free(pair_at);
    lv->edge_count = e;
    free(use_owner);
    return SK_OK;
}
