/* Cholesky factorisations (dense_internal.h) of the free-DOF block of the
 * equilibrium matrix (eq. 3.17), cached by free set until K, A or W change: pinning a
 * slider or reaching a limit changes the free set, a new input value does not. */
#include <string.h>

#include "models/hand/dense_internal.h"
#include "models/hand/solver_internal.h"

const sk_hand_factor *sk__hand_factor(sk_hand_solver *s, uint64_t key, sk_error *err)
{
    int size = s->desc.cache_size;
    sk_hand_factor *slot = NULL;
    for (int i = 0; i < size; i++) {
        sk_hand_factor *f = &s->cache[i];
        if (f->valid && f->key == key) {
            f->last_use = ++s->clock;
            return f;
        }
    }
    /* least recently used (or empty) slot */
    for (int i = 0; i < size; i++) {
        sk_hand_factor *f = &s->cache[i];
        if (!f->valid) {
            slot = f;
            break;
        }
        if (!slot || f->last_use < slot->last_use) slot = f;
    }
    int nf = 0;
    for (int i = 0; i < N_DOF; i++)
        if (!(key >> i & 1)) slot->free_dof[nf++] = i;
    bool with_lut = (key & SK_HAND_FACTOR_LUT_BIT) != 0;
    for (int b = 0; b < nf; b++) {
        const double *col = s->h + (size_t)slot->free_dof[b] * N_DOF;
        for (int a = 0; a < nf; a++) slot->l[b * nf + a] = col[slot->free_dof[a]];
        if (with_lut) slot->l[b * nf + b] += s->lut_curv[slot->free_dof[b]];
    }
    slot->nf = nf;
    slot->key = key;
    slot->valid = false;
    if (nf > 0) {
        int info = sk__hand_cholesky_at(slot->l, nf);
        if (info != 0) {
            sk_fail(err, SK_ERROR_NUMERIC,
                    "equilibrium matrix K + A'WA is not positive definite (at %s)",
                    info > 0 ? sk_hand_dof(slot->free_dof[info - 1])->name : "?");
            return NULL;
        }
    }
    slot->valid = true;
    slot->last_use = ++s->clock;
    return slot;
}

void sk__hand_factor_solve(const sk_hand_factor *f, double *rhs)
{
    sk__hand_cholesky_solve(f->l, f->nf, rhs, 1);
}
