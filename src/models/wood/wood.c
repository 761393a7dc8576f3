/* The wood solid texture (Kawai 2000): the tree object, built once from a desc (the ring,
 * phase and shading tables of sec. 4.4, 6 and 7); eval.c evaluates points on it. */
#include <stdlib.h>

#include "models/wood/wood_internal.h"

const sk_wood_desc *sk_wood_get_desc(const sk_wood *wood) { return &wood->desc; }

void sk_wood_get_stats(const sk_wood *wood, sk_wood_stats *stats) { *stats = wood->stats; }

void sk_wood_destroy(sk_wood *wood)
{
    if (!wood) return;
    sk__rings_free(&wood->rings);
    sk__grain_free(&wood->grain);
    free(wood);
}

sk_result sk_wood_create(const sk_wood_desc *desc, sk_wood **out, sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "wood: no output pointer");
    *out = NULL;
    double start = sk_time_seconds();
    sk_wood_desc resolved = sk_wood_desc_resolved(desc);
    sk_result r = sk_wood_desc_validate(&resolved, err);
    if (r != SK_OK) return r;
    sk_wood *w = calloc(1, sizeof *w);
    if (!w) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "wood: out of memory");
    w->desc = resolved;
    sk__wood_frame_init(&w->frame, &resolved.transform);
    w->axis = sk__wood_frame_dir_to_scene(&w->frame, sk_v3f(0, 1, 0));
    r = sk__rings_build(&w->rings, &resolved, err);
    if (r == SK_OK) r = sk__grain_build(&w->grain, &resolved, w->rings.t_max, err);
    if (r != SK_OK) {
        sk_wood_destroy(w);
        return r;
    }
    sk__vessels_init(&w->vessels, &resolved);
    sk__attributes_init(&w->attr, &resolved);
    sk__knots_init(&w->knots, &resolved);
    sk__rays_init(&w->rays, &resolved);
    sk__shading_init(&w->shading, &resolved);
    w->stats.memory_bytes = sizeof *w + sk__rings_memory(&w->rings) + sk__grain_memory(&w->grain);
    w->stats.ring_count = w->rings.years;
    w->stats.ring_table_size[0] = w->rings.nt;
    w->stats.ring_table_size[1] = w->rings.ntheta + 1;
    w->stats.phase_table_size[0] = w->grain.dg ? w->grain.nt : 0;
    w->stats.phase_table_size[1] = w->grain.dg ? w->grain.ny + 1 : 0;
    w->stats.setup_seconds = sk_time_seconds() - start;
    *out = w;
    return SK_OK;
}
