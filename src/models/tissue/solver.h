/* The spring solver of the simulation behind one interface, so another method (e.g.
 * projective dynamics with a prefactored matrix, or a build without OpenMP) can take the
 * place of the one used. One call advances the fat and skin points through one internal
 * step of the spring network: on entry `x` holds every point's predicted position (free
 * points: their inertial prediction x_n + h v_n; muscle and bone points: where the bones
 * put them at the step's end) and `base` the positions at the step's start; on return the
 * free points are where the springs put them. Every free point is also tethered by a
 * zero-length spring to `target` (where the tissue carries it at the step's end; `target_base`
 * at its start, for the tether's damping). `step` is called by every thread of an
 * enclosing OpenMP parallel region (or by one thread outside any), and shares its work
 * with orphaned worksharing loops. Results must not depend on the thread count. */
#ifndef SK_TISSUE_SOLVER_H
#define SK_TISSUE_SOLVER_H

#include "models/tissue/tissue_internal.h"

typedef struct sk__solver sk__solver;

typedef struct sk__solver_ops {
    const char *name;
    sk_result (*create)(const sk_tissue_model *m, double step_seconds, sk__solver **out,
                        sk_error *err);
    void (*destroy)(sk__solver *s);
    void (*step)(sk__solver *s, double *x, const double *base, const double *target,
                 const double *target_base);
} sk__solver_ops;

/* XPBD with one iteration per substep (Macklin et al. 2016, 2019). */
extern const sk__solver_ops sk__solver_xpbd;
/* Whether an XPBD solver takes its AVX2 path (where it has one: on by default where the
 * processor runs AVX2; the same bits either way). */
void sk__solver_xpbd_use_vectors(sk__solver *s, bool on);

/* Per-spring constants every solver derives the same way from the model's material:
 * stiffness (N/m) and damping coefficient c = 2 zeta sqrt(k mu) (N s/m) with mu the
 * reduced mass of the two ends (a driven end has infinite mass). */
void sk__spring_constants(const sk_tissue_model *m, size_t s, double *stiffness, double *damping);

#endif
